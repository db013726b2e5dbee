// The regions of a tetrahedral mesh (spec/mesh3d.md M23, io/regions.h)
// against an independent count: the boundary as the vertex triples met once
// (a std::map over every face), the components by a search over shared
// triangles, and each boundary triangle's orientation by the geometry (its
// normal points away from its tetrahedron's fourth vertex).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "bccmis/io/regions.h"
#include "bccmis/io/tet_faces.h"

namespace bccmis::io {
namespace {

using Tet = std::array<std::uint32_t, 4>;
using Tri = std::array<std::uint32_t, 3>;
using Vec = std::array<double, 3>;

struct Mesh {
  std::vector<Vec> vertices;
  std::vector<Tet> tets;
};

double orient(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  const Vec u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]},
      w{d[0] - a[0], d[1] - a[1], d[2] - a[2]};
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/// Unit cubes at the integer corners `at`, each split into the 6 Kuhn
/// tetrahedra along its main diagonal, positively oriented; cubes that touch
/// share their vertices.
Mesh kuhn_cubes(const std::vector<std::array<int, 3>>& at) {
  Mesh m;
  std::map<std::array<int, 3>, std::uint32_t> index;
  auto vertex = [&](std::array<int, 3> p) {
    auto [it, fresh] = index.emplace(p, static_cast<std::uint32_t>(m.vertices.size()));
    if (fresh) m.vertices.push_back({double(p[0]), double(p[1]), double(p[2])});
    return it->second;
  };
  static constexpr int kPermutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& c : at)
    for (const auto& perm : kPermutations) {
      std::array<int, 3> p = c;
      Tet t{};
      t[0] = vertex(p);
      for (int k = 0; k < 3; ++k) {
        ++p[static_cast<std::size_t>(perm[k])];
        t[static_cast<std::size_t>(k + 1)] = vertex(p);
      }
      if (orient(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], m.vertices[t[3]]) < 0) std::swap(t[2], t[3]);
      m.tets.push_back(t);
    }
  return m;
}

void check_against_independent_count(const Mesh& m, std::uint32_t expected_components) {
  // Faces by sorted triple: the tetrahedra of each.
  std::map<Tri, std::vector<std::uint32_t>> faces;
  for (std::uint32_t t = 0; t < m.tets.size(); ++t)
    for (int skip = 0; skip < 4; ++skip) {
      Tri f{};
      for (int i = 0, n = 0; i < 4; ++i)
        if (i != skip) f[static_cast<std::size_t>(n++)] = m.tets[t][static_cast<std::size_t>(i)];
      std::sort(f.begin(), f.end());
      faces[f].push_back(t);
    }
  // Components by a search over shared triangles.
  std::vector<std::uint32_t> component(m.tets.size(), UINT32_MAX);
  std::uint32_t count = 0;
  for (std::uint32_t seed = 0; seed < m.tets.size(); ++seed) {
    if (component[seed] != UINT32_MAX) continue;
    std::vector<std::uint32_t> stack{seed};
    component[seed] = count;
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      for (const auto& [f, ts] : faces)
        if (std::find(ts.begin(), ts.end(), t) != ts.end())
          for (const std::uint32_t u : ts)
            if (component[u] == UINT32_MAX) component[u] = count, stack.push_back(u);
    }
    ++count;
  }
  ASSERT_EQ(count, expected_components);

  std::vector<Tri> by_triple;
  const Regions r = regions_of(m.tets, &by_triple);
  EXPECT_EQ(r.count, count);
  EXPECT_EQ(r.tet_component, component);
  // The boundary in triple order: the triples met once, in the map's order.
  std::vector<Tri> once;
  for (const auto& [f, ts] : faces)
    if (ts.size() == 1) once.push_back(f);
  ASSERT_EQ(by_triple.size(), once.size());
  for (std::size_t i = 0; i < once.size(); ++i) {
    Tri sorted = by_triple[i];
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, once[i]) << i;
  }
  // The boundary by component: the same triangles, stably sorted by
  // component, each outward and labelled with its tetrahedron's component.
  ASSERT_EQ(r.boundary.size(), once.size());
  std::vector<Tri> expected = by_triple;
  std::stable_sort(expected.begin(), expected.end(), [&](const Tri& a, const Tri& b) {
    Tri sa = a, sb = b;
    std::sort(sa.begin(), sa.end());
    std::sort(sb.begin(), sb.end());
    return component[faces[sa][0]] < component[faces[sb][0]];
  });
  EXPECT_EQ(r.boundary, expected);
  for (std::size_t j = 0; j < r.boundary.size(); ++j) {
    const Tri& f = r.boundary[j];
    Tri key = f;
    std::sort(key.begin(), key.end());
    const std::uint32_t t = faces[key][0];
    EXPECT_EQ(r.boundary_component[j], component[t]);
    std::uint32_t fourth = 0;
    for (const std::uint32_t v : m.tets[t])
      if (std::find(f.begin(), f.end(), v) == f.end()) fourth = v;
    EXPECT_LT(orient(m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]], m.vertices[fourth]), 0)
        << "boundary triangle " << j << " faces inward";
  }
}

TEST(Regions, OneCubeIsOneComponentWithTwelveBoundaryTriangles) {
  const Mesh m = kuhn_cubes({{0, 0, 0}});
  check_against_independent_count(m, 1);
  EXPECT_EQ(regions_of(m.tets).boundary.size(), 12U);
}

TEST(Regions, CubesJoinThroughFacesOnlyNotEdgesOrCorners) {
  // Two cubes sharing a face (one component), one cube meeting them along
  // an edge only, one at a corner only, one apart: 4 components.
  const Mesh m = kuhn_cubes({{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 2, 1}, {6, 0, 0}});
  check_against_independent_count(m, 4);
}

/// `count` tetrahedra (0, i, i + 1, apex) around the axis through vertex 0
/// and the apex, over an open arc of a circle: each tetrahedron shares the
/// triangle (0, i + 1, apex) with the next; the fan is centred at x = x0.
void add_fan(Mesh& m, std::uint32_t count, double x0) {
  const auto first = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.push_back({x0, 0, 0});
  for (std::uint32_t i = 0; i <= count; ++i) {
    const double a = 6.0 * i / count;  // radians, short of a full turn
    m.vertices.push_back({x0 + std::cos(a), std::sin(a), 0.5});
  }
  const auto apex = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.push_back({x0, 0, 1});
  for (std::uint32_t i = 1; i <= count; ++i) {
    Tet t{first, first + i, first + i + 1, apex};
    if (orient(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], m.vertices[t[3]]) < 0) std::swap(t[2], t[3]);
    m.tets.push_back(t);
  }
}

TEST(Regions, AVertexWithManyFacesIsGroupedAsAnyOther) {
  // 40 tetrahedra file 120 faces under their smallest vertex, more than
  // the 64 the grouping sorts by insertion alone (spec/mesh3d.md M23); a
  // second fan apart is a second component.
  Mesh m;
  add_fan(m, 40, 0);
  add_fan(m, 3, 5);
  check_against_independent_count(m, 2);
  EXPECT_EQ(regions_of(m.tets).boundary.size(), 2U * 40 + 2 + 2U * 3 + 2);
}

/// Every group of for_each_face_group_as<Id> as (sorted triple, its face
/// ids), both in the order visited.
template <class Id>
std::vector<std::pair<Tri, std::vector<std::size_t>>> groups_with(const Mesh& m) {
  std::vector<std::pair<Tri, std::vector<std::size_t>>> groups;
  detail::for_each_face_group_as<Id>(m.tets, m.vertices.size(), [&](const std::size_t* first, const std::size_t* last) {
    Tri key = outward_face(m.tets, *first);
    std::sort(key.begin(), key.end());
    groups.emplace_back(key, std::vector<std::size_t>(first, last));
  });
  return groups;
}

TEST(Regions, FaceIdsOfThirtyTwoAndSixtyFourBitsGroupAsTheIndependentCount) {
  // spec/mesh3d.md M26: the filed ids are 32-bit below 2^32 faces; the
  // 64-bit ids of larger meshes give the same groups. Against the faces
  // grouped by a std::map of their sorted triples (the ids of a group
  // in increasing order, the groups in triple order), on cubes and on a
  // vertex filing more than 64 faces.
  Mesh m = kuhn_cubes({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 1}});
  add_fan(m, 40, 10);
  std::map<Tri, std::vector<std::size_t>> faces;
  for (std::size_t id = 0; id < 4 * m.tets.size(); ++id) {
    Tri key = outward_face(m.tets, id);
    std::sort(key.begin(), key.end());
    faces[key].push_back(id);
  }
  const std::vector<std::pair<Tri, std::vector<std::size_t>>> expected(faces.begin(), faces.end());
  const auto narrow = groups_with<std::uint32_t>(m), wide = groups_with<std::size_t>(m);
  EXPECT_EQ(narrow, wide);  // the same groups with their ids in the same order
  // M23 leaves the order within a group open (std::sort above 64 faces).
  auto sorted = narrow;
  for (auto& [key, ids] : sorted) std::sort(ids.begin(), ids.end());
  EXPECT_EQ(sorted, expected);
}

TEST(Regions, AnEmptyMeshHasNothing) {
  std::vector<Tri> by_triple{{1, 2, 3}};
  const Regions r = regions_of({}, &by_triple);
  EXPECT_EQ(r.count, 0U);
  EXPECT_TRUE(r.boundary.empty());
  EXPECT_TRUE(by_triple.empty());
}

}  // namespace
}  // namespace bccmis::io
