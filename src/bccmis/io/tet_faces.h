// bccmis::io: the faces of a tetrahedral mesh grouped by their vertices, in
// linear time plus a sort of each vertex's few faces (spec/stuffing.md S13,
// spec/mesh3d.md M23). The boundary is the groups of one face; the
// components join the tetrahedra of every larger group.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace bccmis::io {

using Tets = std::vector<std::array<std::uint32_t, 4>>;

/// Face id 4 t + i: the face opposite v_i of tetrahedron t, its vertices in
/// the order that is outward for a positively oriented tetrahedron.
inline std::array<std::uint32_t, 3> outward_face(const Tets& tets, std::size_t id) {
  static constexpr std::size_t kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  const auto& t = tets[id / 4];
  const std::size_t* f = kFaces[id % 4];
  return {t[f[0]], t[f[1]], t[f[2]]};
}

/// Tetrahedron t's vertices sorted (a five-comparator network), with the
/// index in t of each: the face opposite sorted[k] is face 4 t + at[k] and
/// its sorted vertex triple is `sorted` without sorted[k].
struct SortedCorners {
  std::array<std::uint32_t, 4> sorted;
  std::array<std::uint8_t, 4> at{0, 1, 2, 3};
  explicit SortedCorners(const std::array<std::uint32_t, 4>& t) : sorted(t) {
    const auto order = [this](std::size_t a, std::size_t b) {
      if (sorted[b] < sorted[a]) std::swap(sorted[a], sorted[b]), std::swap(at[a], at[b]);
    };
    order(0, 1), order(2, 3), order(0, 2), order(1, 3), order(1, 2);
  }
};

namespace detail {

/// The key of face `id` (4 t + i) as for_each_face_group files it: its
/// sorted vertex triple (lo, mid, high) without lo, mid << 32 | high.
inline std::uint64_t face_key(const Tets& tets, std::size_t id) {
  static constexpr std::size_t kOthers[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  const auto& t = tets[id / 4];
  const std::size_t* o = kOthers[id % 4];
  std::uint32_t a = t[o[0]], b = t[o[1]], c = t[o[2]];
  if (b < a) std::swap(a, b);
  if (c < b) std::swap(b, c);
  if (b < a) std::swap(a, b);
  return std::uint64_t{b} << 32 | c;
}

/// for_each_face_group with the filed face ids stored as Id (M26).
template <class Id, class Visit>
void for_each_face_group_as(const Tets& tets, std::size_t vertex_count, const Visit& visit) {
  struct Filed {
    std::uint64_t key;  // mid << 32 | high
    std::size_t id;
  };
  std::vector<std::size_t> start(vertex_count + 1, 0);
  for (const auto& t : tets) {
    const SortedCorners c(t);
    start[c.sorted[0] + std::size_t{1}] += 3;  // the faces without sorted[1], [2], [3]
    start[c.sorted[1] + std::size_t{1}] += 1;  // the face without sorted[0]
  }
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<Id> filed(start.back());
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < tets.size(); ++t) {
      const SortedCorners c(tets[t]);
      const auto& s = c.sorted;
      filed[next[s[1]]++] = static_cast<Id>(4 * t + c.at[0]);
      filed[next[s[0]]++] = static_cast<Id>(4 * t + c.at[1]);
      filed[next[s[0]]++] = static_cast<Id>(4 * t + c.at[2]);
      filed[next[s[0]]++] = static_cast<Id>(4 * t + c.at[3]);
    }
  }
  std::vector<Filed> keyed;
  std::vector<std::size_t> group;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    if (start[v] == start[v + 1]) continue;  // no face filed here
    // The vertex's faces with their keys, in the order they were filed.
    keyed.clear();
    for (std::size_t f = start[v]; f < start[v + 1]; ++f) keyed.push_back({face_key(tets, filed[f]), filed[f]});
    Filed* const first = keyed.data();
    Filed* const last = first + keyed.size();
    // A lattice mesh's vertex files a few dozen faces: insertion sort them;
    // std::sort a vertex of any other mesh's that files many.
    if (last - first > 64) std::sort(first, last, [](const Filed& a, const Filed& b) { return a.key < b.key; });
    for (Filed* f = first + 1; f < last; ++f) {
      const Filed x = *f;
      Filed* g = f;
      for (; g > first && x.key < (g - 1)->key; --g) *g = *(g - 1);
      *g = x;
    }
    for (Filed* run = first; run != last;) {
      Filed* end = run + 1;
      while (end != last && end->key == run->key) ++end;
      group.clear();
      for (Filed* f = run; f != end; ++f) group.push_back(f->id);
      visit(group.data(), group.data() + group.size());
      run = end;
    }
  }
}

}  // namespace detail

/// visit(first, last) for every group of face ids [first, last) with the same
/// three vertices, the groups in increasing order of their sorted vertex
/// triples. `vertex_count` exceeds every vertex index. Each tetrahedron's
/// vertices are sorted once (SortedCorners); every face's id is filed under
/// its smallest vertex (a counting sort), then each vertex's few faces are
/// given their key (the other two vertices packed as mid << 32 | high,
/// ordered as the pair) and sorted by it. The filed ids are 32-bit when
/// every face id fits (M26: 16 bytes a tetrahedron instead of 64).
template <class Visit>
void for_each_face_group(const Tets& tets, std::size_t vertex_count, const Visit& visit) {
  if (4 * tets.size() <= std::size_t{UINT32_MAX} + 1)
    detail::for_each_face_group_as<std::uint32_t>(tets, vertex_count, visit);
  else
    detail::for_each_face_group_as<std::size_t>(tets, vertex_count, visit);
}

}  // namespace bccmis::io
