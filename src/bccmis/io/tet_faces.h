// bccmis::io: the faces of a tetrahedral mesh grouped by their vertices, in
// linear time plus a sort of each vertex's few faces (spec/stuffing.md S13,
// spec/mesh3d.md M23). The boundary is the groups of one face; the
// components join the tetrahedra of every larger group.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
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

/// visit(first, last) for every group of face ids [first, last) with the same
/// three vertices, the groups in increasing order of their sorted vertex
/// triples. `vertex_count` exceeds every vertex index. Every face is filed
/// under its smallest vertex (a counting sort), then each vertex's faces are
/// sorted by the other two.
template <class Visit>
void for_each_face_group(const Tets& tets, std::size_t vertex_count, const Visit& visit) {
  struct Filed {
    std::uint32_t mid, high;
    std::size_t id;
  };
  std::vector<std::size_t> start(vertex_count + 1, 0);
  for (std::size_t id = 0; id < 4 * tets.size(); ++id) {
    const auto f = outward_face(tets, id);
    ++start[std::min({f[0], f[1], f[2]}) + std::size_t{1}];
  }
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<Filed> filed(start.back());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (std::size_t id = 0; id < 4 * tets.size(); ++id) {
    auto key = outward_face(tets, id);
    std::sort(key.begin(), key.end());
    filed[next[key[0]]++] = {key[1], key[2], id};
  }
  const auto before = [](const Filed& a, const Filed& b) { return std::tie(a.mid, a.high) < std::tie(b.mid, b.high); };
  std::vector<std::size_t> group;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const auto first = filed.begin() + static_cast<std::ptrdiff_t>(start[v]),
               last = filed.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
    std::sort(first, last, before);
    for (auto run = first; run != last;) {
      auto end = run + 1;
      while (end != last && !before(*run, *end)) ++end;
      group.clear();
      for (auto f = run; f != end; ++f) group.push_back(f->id);
      visit(group.data(), group.data() + group.size());
      run = end;
    }
  }
}

}  // namespace bccmis::io
