#include "bccmis/io/regions.h"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace bccmis::io {

namespace {

/// Union-find over the tetrahedra.
struct Components {
  std::vector<std::uint32_t> parent;
  explicit Components(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

/// One face of one tetrahedron: its sorted vertices, the tetrahedron, and
/// the face as oriented outward.
struct Face {
  std::array<std::uint32_t, 3> key;
  std::uint32_t tet;
  std::array<std::uint32_t, 3> outward;
};

}  // namespace

Regions regions_of(const std::vector<std::array<std::uint32_t, 4>>& tets) {
  // The face opposite v_i of a positive tetrahedron, outward.
  static constexpr std::size_t kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  std::vector<Face> faces;
  faces.reserve(4 * tets.size());
  for (std::uint32_t t = 0; t < tets.size(); ++t)
    for (const auto& f : kFaces) {
      const std::array<std::uint32_t, 3> tri{tets[t][f[0]], tets[t][f[1]], tets[t][f[2]]};
      std::array<std::uint32_t, 3> key = tri;
      std::sort(key.begin(), key.end());
      faces.push_back({key, t, tri});
    }
  std::sort(faces.begin(), faces.end(),
            [](const Face& a, const Face& b) { return std::tie(a.key, a.tet) < std::tie(b.key, b.tet); });
  Components components(tets.size());
  std::vector<const Face*> single;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key) components.join(faces[i].tet, faces[j++].tet);
    if (j == i + 1) single.push_back(&faces[i]);
    i = j;
  }
  Regions r;
  r.tet_component.resize(tets.size());
  std::vector<std::uint32_t> number(tets.size(), UINT32_MAX);  // by root
  for (std::uint32_t t = 0; t < tets.size(); ++t) {
    const std::uint32_t root = components.find(t);
    if (number[root] == UINT32_MAX) number[root] = r.count++;
    r.tet_component[t] = number[root];
  }
  std::stable_sort(single.begin(), single.end(),
                   [&](const Face* a, const Face* b) { return r.tet_component[a->tet] < r.tet_component[b->tet]; });
  for (const Face* f : single) {
    r.boundary.push_back(f->outward);
    r.boundary_component.push_back(r.tet_component[f->tet]);
  }
  return r;
}

}  // namespace bccmis::io
