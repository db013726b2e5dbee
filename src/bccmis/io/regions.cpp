#include "bccmis/io/regions.h"

#include <algorithm>
#include <cstddef>
#include <numeric>

#include "bccmis/io/tet_faces.h"

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

}  // namespace

Regions regions_of(const std::vector<std::array<std::uint32_t, 4>>& tets,
                   std::vector<std::array<std::uint32_t, 3>>* boundary_by_triple) {
  std::size_t vertex_count = 0;
  for (const auto& t : tets)
    vertex_count = std::max<std::size_t>(vertex_count, *std::max_element(t.begin(), t.end()) + std::size_t{1});
  // The groups of faces in the order of their sorted vertex triples
  // (io/tet_faces.h): a larger group joins its tetrahedra, a single face is
  // a boundary triangle.
  Components components(tets.size());
  std::vector<std::size_t> single;
  for_each_face_group(tets, vertex_count, [&](const std::size_t* first, const std::size_t* last) {
    if (last - first == 1) single.push_back(*first);
    for (const std::size_t* f = first + 1; f < last; ++f)
      components.join(static_cast<std::uint32_t>(*first / 4), static_cast<std::uint32_t>(*f / 4));
  });
  Regions r;
  r.tet_component.resize(tets.size());
  std::vector<std::uint32_t> number(tets.size(), UINT32_MAX);  // by root
  for (std::uint32_t t = 0; t < tets.size(); ++t) {
    const std::uint32_t root = components.find(t);
    if (number[root] == UINT32_MAX) number[root] = r.count++;
    r.tet_component[t] = number[root];
  }
  if (boundary_by_triple != nullptr) {
    boundary_by_triple->clear();
    boundary_by_triple->reserve(single.size());
    for (const std::size_t f : single) boundary_by_triple->push_back(outward_face(tets, f));
  }
  std::stable_sort(single.begin(), single.end(),
                   [&](std::size_t a, std::size_t b) { return r.tet_component[a / 4] < r.tet_component[b / 4]; });
  r.boundary.reserve(single.size());
  r.boundary_component.reserve(single.size());
  for (const std::size_t f : single) {
    r.boundary.push_back(outward_face(tets, f));
    r.boundary_component.push_back(r.tet_component[f / 4]);
  }
  return r;
}

}  // namespace bccmis::io
