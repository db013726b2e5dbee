// The graded BCC tetrahedral mesh (spec/mesh3d.md): the hand counts and
// volumes of §4, the five tetrahedron shapes and their dihedral angles, the
// mesh facts (tiling, conformity, edges, angles) in every state of random
// operation sequences, exact orientation at coordinates near 2^62, and the
// three writers read back. Expected values come from spec/mesh3d.md.
#include "bccmis/d3/mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bccmis/io/medit.h"
#include "bccmis/io/msh.h"
#include "bccmis/io/vtu.h"
#include "util.h"

namespace bccmis::d3 {
namespace {

using Tets = std::vector<Tet>;

std::int64_t coord(const Point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

std::int64_t extent(const LatticeSize& size, int axis) {
  return (axis == 0 ? size.W : axis == 1 ? size.H : size.D) * (std::int64_t{1} << (size.L + 1));
}

// 6 times the signed volume in 64-bit integers (the tests' coordinates are
// below 2^16), independent of the code under test.
std::int64_t det6(const Tet& t) {
  const std::int64_t a[3] = {t[1].x - t[0].x, t[1].y - t[0].y, t[1].z - t[0].z};
  const std::int64_t b[3] = {t[2].x - t[0].x, t[2].y - t[0].y, t[2].z - t[0].z};
  const std::int64_t c[3] = {t[3].x - t[0].x, t[3].y - t[0].y, t[3].z - t[0].z};
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

std::int64_t total_det6(const Tets& tets) {
  std::int64_t sum = 0;
  for (const Tet& t : tets) sum += det6(t);
  return sum;
}

std::int64_t box_det6(const LatticeSize& size) { return 6 * extent(size, 0) * extent(size, 1) * extent(size, 2); }

// The 6 dihedral angles of t in degrees, sorted, in long double.
std::vector<long double> test_dihedral_angles(const Tet& t) {
  using V = std::array<long double, 3>;
  auto sub = [](const Point& p, const Point& q) {
    return V{static_cast<long double>(p.x - q.x), static_cast<long double>(p.y - q.y),
             static_cast<long double>(p.z - q.z)};
  };
  auto cross = [](const V& a, const V& b) {
    return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto dot = [](const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  std::vector<long double> out;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j) {
      std::size_t k = 0;
      while (k == i || k == j) ++k;
      std::size_t l = 0;
      while (l == i || l == j || l == k) ++l;
      const V e = sub(t[j], t[i]);
      const V n1 = cross(e, sub(t[k], t[i])), n2 = cross(e, sub(t[l], t[i]));
      const long double c = dot(n1, n2) / std::sqrt(dot(n1, n1) * dot(n2, n2));
      out.push_back(std::acos(std::clamp(c, -1.0L, 1.0L)) * 180.0L / 3.141592653589793238462643383279502884L);
    }
  std::sort(out.begin(), out.end());
  return out;
}

// Rounded to 1e-6 degrees, for comparing multisets of angles.
std::vector<long long> rounded(const std::vector<long double>& angles) {
  std::vector<long long> out;
  for (const long double a : angles) out.push_back(std::llround(a * 1e6L));
  return out;
}

std::vector<long long> degrees(std::initializer_list<long long> d) {
  std::vector<long long> out;
  for (const long long v : d) out.push_back(v * 1000000);
  return out;
}

// spec/mesh3d.md M14: the five shapes, on a leaf of side 2 centred at 0.
struct Shape {
  const char* name;
  Tet tet;
  std::int64_t six_volume;
  std::vector<long long> angles;
};

std::vector<Shape> shapes() {
  const Point o{0, 0, 0};
  return {
      {"equal, whole edge", {o, {0, 0, -2}, {-1, -1, -1}, {1, -1, -1}}, 4, degrees({60, 60, 60, 60, 90, 90})},
      {"equal, half edge", {o, {0, 0, -2}, {-1, -1, -1}, {0, -1, -1}}, 2, degrees({45, 60, 60, 90, 90, 90})},
      {"hull, whole edge", {o, {0, 0, -1}, {-1, -1, -1}, {1, -1, -1}}, 2, degrees({45, 60, 60, 90, 90, 90})},
      {"hull or coarse, half edge", {o, {0, 0, -1}, {-1, -1, -1}, {0, -1, -1}}, 1, degrees({45, 45, 60, 90, 90, 90})},
      {"fine split side", {o, {1, 1, -1}, {-1, -1, -1}, {1, -1, -1}}, 4, degrees({45, 45, 60, 60, 90, 120})},
  };
}

bool is_hull_vertex(const Graph& g, const Point& p) { return !g.is_node(p) && !g.is_center(p); }

// Which rule of spec/mesh3d.md made t: M5 equal, M6 coarse side, M7 fine
// side, M8 hull; judged from the apex t[1] and the leaf t[0].
enum class Case { equal, coarse, fine, hull };

Case case_of(const Graph& g, const Tet& t) {
  if (g.is_center(t[1])) return Case::equal;
  if (is_hull_vertex(g, t[1])) return Case::hull;
  const std::int64_t h = cell_side(g.size, g.level_of(t[0])) / 2;
  const bool corner =
      std::abs(t[1].x - t[0].x) == h && std::abs(t[1].y - t[0].y) == h && std::abs(t[1].z - t[0].z) == h;
  return corner ? Case::fine : Case::coarse;
}

std::map<Case, std::size_t> case_counts(const Graph& g, const Tets& tets) {
  std::map<Case, std::size_t> out;
  for (const Tet& t : tets) ++out[case_of(g, t)];
  return out;
}

using Edge = std::pair<Point, Point>;
Edge edge(const Point& a, const Point& b) { return a < b ? Edge{a, b} : Edge{b, a}; }

// The green edges and split-face diagonals of spec/mesh3d.md M12, computed
// from the leaf cubes and the node set (a cube edge holds its two corners and,
// when it is a node, its midpoint: lattice3d.md F3).
std::set<Edge> expected_node_node_edges(const Graph& g) {
  std::set<Edge> out;
  for (const Point& u : g.C) {
    const std::int64_t h = cell_side(g.size, g.level_of(u)) / 2;
    for (int i = 0; i < 8; ++i)
      for (int axis = 0; axis < 3; ++axis) {
        if ((i >> axis) & 1) continue;  // each edge once, from its lower corner
        const Point a{u.x + ((i & 1) ? h : -h), u.y + ((i & 2) ? h : -h), u.z + ((i & 4) ? h : -h)};
        Point b = a, m = a;
        (axis == 0 ? b.x : axis == 1 ? b.y : b.z) += 2 * h;
        (axis == 0 ? m.x : axis == 1 ? m.y : m.z) += h;
        if (g.is_node(m)) {
          out.insert(edge(a, m));
          out.insert(edge(m, b));
        } else {
          out.insert(edge(a, b));
        }
      }
    // Split faces seen from the coarse side: the face center is a node.
    for (int axis = 0; axis < 3; ++axis)
      for (const std::int64_t side : {-h, h}) {
        Point f = u;
        (axis == 0 ? f.x : axis == 1 ? f.y : f.z) += side;
        if (!g.is_node(f)) continue;
        for (const std::int64_t da : {-h, h})
          for (const std::int64_t db : {-h, h}) {
            Point c = f;
            (axis == 0 ? c.y : c.x) += da;
            (axis == 2 ? c.y : c.z) += db;
            out.insert(edge(f, c));
          }
      }
  }
  return out;
}

bool on_domain_boundary(const LatticeSize& size, const std::array<Point, 3>& tri) {
  for (int axis = 0; axis < 3; ++axis)
    for (const std::int64_t v : {std::int64_t{0}, extent(size, axis)})
      if (coord(tri[0], axis) == v && coord(tri[1], axis) == v && coord(tri[2], axis) == v) return true;
  return false;
}

// Every fact of spec/mesh3d.md §3 that a state allows checking; the first
// problem, or "".
std::string mesh_problem(const Graph& g, const Tets& tets) {
  if (!std::is_sorted(tets.begin(), tets.end())) return "not sorted";
  if (std::adjacent_find(tets.begin(), tets.end()) != tets.end()) return "a tetrahedron twice";
  const auto name = [](const Tet& t) {
    return to_string(t[0]) + ' ' + to_string(t[1]) + ' ' + to_string(t[2]) + ' ' + to_string(t[3]);
  };
  // M3: positive orientation, v[0] a center.
  for (const Tet& t : tets) {
    if (det6(t) <= 0) return "not positively oriented: " + name(t);
    if (!g.is_center(t[0])) return "first vertex not a center: " + name(t);
  }
  // M10: the volumes tile the box.
  if (total_det6(tets) != box_det6(g.size))
    return "6 * volume sums to " + std::to_string(total_det6(tets)) + ", not " + std::to_string(box_det6(g.size));
  // M11: conformity.
  std::map<std::array<Point, 3>, int> triangles;
  for (const Tet& t : tets)
    for (std::size_t skip = 0; skip < 4; ++skip) {
      std::array<Point, 3> tri{};
      std::size_t k = 0;
      for (std::size_t i = 0; i < 4; ++i)
        if (i != skip) tri[k++] = t[i];
      std::sort(tri.begin(), tri.end());
      ++triangles[tri];
    }
  for (const auto& [tri, count] : triangles) {
    const int want = on_domain_boundary(g.size, tri) ? 1 : 2;
    if (count != want)
      return "triangle " + to_string(tri[0]) + ' ' + to_string(tri[1]) + ' ' + to_string(tri[2]) + " in " +
             std::to_string(count) + " tetrahedra, not " + std::to_string(want);
  }
  // M12: the edges by kind.
  std::set<Edge> center_node, node_node;
  for (const Tet& t : tets)
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j) {
        const Point &a = t[i], &b = t[j];
        if (g.is_center(a) && g.is_node(b)) center_node.insert({a, b});
        if (g.is_node(a) && g.is_center(b)) center_node.insert({b, a});
        if (g.is_node(a) && g.is_node(b)) node_node.insert(edge(a, b));
        if (is_hull_vertex(g, a) || is_hull_vertex(g, b)) {
          const Point& hv = is_hull_vertex(g, a) ? a : b;
          int on = 0;
          for (int axis = 0; axis < 3; ++axis) on += coord(hv, axis) == 0 || coord(hv, axis) == extent(g.size, axis);
          if (on != 1) return "vertex " + to_string(hv) + " is neither in N, C nor a domain-face point";
        }
      }
  std::set<Edge> stored;
  for (const Point& u : g.C)
    for (const Point& n : g.nbr(u)) stored.insert({u, n});
  if (center_node != stored) return "the center-node edges are not the stored graph edges";
  if (node_node != expected_node_node_edges(g)) return "the node-node edges are not the green edges and diagonals";
  // M14: every tetrahedron is one of the five shapes; angles in [45, 120].
  std::set<std::vector<long long>> known;
  for (const Shape& s : shapes()) known.insert(s.angles);
  for (const Tet& t : tets) {
    const std::vector<long double> angles = test_dihedral_angles(t);
    if (angles.front() < 45.0L - 1e-9L || angles.back() > 120.0L + 1e-9L) return "angle out of range: " + name(t);
    if (!known.count(rounded(angles))) return "not one of the five shapes: " + name(t);
  }
  return {};
}

std::string lattice_line(const LatticeSize& s) {
  return "lattice " + std::to_string(s.W) + ' ' + std::to_string(s.H) + ' ' + std::to_string(s.D) + ' ' +
         std::to_string(s.L) + '\n';
}

TEST(D3Mesh, FiveShapesAndTheirAngles) {
  // spec/mesh3d.md M14: the table, and the range [45, 120] over all shapes.
  long double lo = 180, hi = 0;
  for (const Shape& s : shapes()) {
    EXPECT_EQ(std::abs(det6(s.tet)), s.six_volume) << s.name;  // the table lists the unsigned volume
    const std::vector<long double> angles = test_dihedral_angles(s.tet);
    EXPECT_EQ(rounded(angles), s.angles) << s.name;
    lo = std::min(lo, angles.front());
    hi = std::max(hi, angles.back());
  }
  EXPECT_NEAR(static_cast<double>(lo), 45.0, 1e-9);
  EXPECT_NEAR(static_cast<double>(hi), 120.0, 1e-9);
}

// The mesh of g: `count` tetrahedra, 6 times their volumes summing to
// `det6`, `cases` of each case (spec/mesh3d.md M3-M8), and no problem.
void expect_mesh(const Graph& g, const Tets& tets, std::size_t count, std::int64_t det6,
                 const std::map<Case, std::size_t>& cases) {
  EXPECT_EQ(tets.size(), count);
  EXPECT_EQ(total_det6(tets), det6);
  EXPECT_EQ(case_counts(g, tets), cases);
  EXPECT_EQ(mesh_problem(g, tets), "");
}

TEST(D3Mesh, OneCube) {
  // spec/mesh3d.md M15: 6 hull faces x 4 segments.
  const Graph g(LatticeSize{1, 1, 1, 0});
  const Tets tets = tetrahedra(g);
  expect_mesh(g, tets, 24u, 48, std::map<Case, std::size_t>{{Case::hull, 24}});
}

TEST(D3Mesh, TwoCubes) {
  // spec/mesh3d.md M16: 4 on the equal face, 10 hull faces x 4.
  const Graph g(LatticeSize{2, 1, 1, 0});
  const Tets tets = tetrahedra(g);
  expect_mesh(g, tets, 44u, 96, std::map<Case, std::size_t>{{Case::equal, 4}, {Case::hull, 40}});
  // M5: the equal face's tetrahedra are whole BCC tetrahedra, emitted from (1,1,1).
  for (const Tet& t : tets)
    if (case_of(g, t) == Case::equal) {
      EXPECT_EQ(t[0], (Point{1, 1, 1}));
      EXPECT_EQ(t[1], (Point{3, 1, 1}));
      EXPECT_EQ(rounded(test_dihedral_angles(t)), degrees({60, 60, 60, 60, 90, 90}));
    }
}

TEST(D3Mesh, RefinedRoot) {
  // spec/mesh3d.md M17: 12 equal faces x 4, 24 hull faces x 4.
  Graph g(LatticeSize{1, 1, 1, 1});
  ASSERT_TRUE(refine(g, {2, 2, 2}).applied());
  const Tets tets = tetrahedra(g);
  expect_mesh(g, tets, 144u, 384, std::map<Case, std::size_t>{{Case::equal, 48}, {Case::hull, 96}});
}

TEST(D3Mesh, SplitFace) {
  // spec/mesh3d.md M18: lattice 2 1 1 2 with (4,4,4) refined.
  Graph g(LatticeSize{2, 1, 1, 2});
  ASSERT_TRUE(refine(g, {4, 4, 4}).applied());
  const Tets tets = tetrahedra(g);
  expect_mesh(g, tets, 168u, 6144,
              std::map<Case, std::size_t>{{Case::equal, 48}, {Case::coarse, 8}, {Case::fine, 8}, {Case::hull, 104}});
  // M6: the coarse side, 8 tetrahedra with apex (8,4,4), one per half edge.
  // M7: 2 per quarter face, with apex (8,4,4) a corner of the fine leaf.
  std::map<Point, std::size_t> fine_per_leaf;
  std::size_t coarse = 0;
  for (const Tet& t : tets) {
    if (case_of(g, t) == Case::coarse) {
      ++coarse;
      EXPECT_EQ(t[0], (Point{12, 4, 4}));
      EXPECT_EQ(t[1], (Point{8, 4, 4}));
      EXPECT_EQ(det6(t), 64);
    }
    if (case_of(g, t) == Case::fine) {
      ++fine_per_leaf[t[0]];
      EXPECT_EQ(t[1], (Point{8, 4, 4}));
      EXPECT_EQ(det6(t), 32);
    }
  }
  EXPECT_EQ(coarse, 8u);
  EXPECT_EQ(fine_per_leaf,
            (std::map<Point, std::size_t>{{{6, 2, 2}, 2}, {{6, 2, 6}, 2}, {{6, 6, 2}, 2}, {{6, 6, 6}, 2}}));
  // The coarse leaf's hull faces: 4 faces with 5 segments, x = 16 with 4.
  std::map<Point, std::size_t> per_hull_vertex;
  for (const Tet& t : tets)
    if (t[0] == Point{12, 4, 4} && case_of(g, t) == Case::hull) ++per_hull_vertex[t[1]];
  EXPECT_EQ(per_hull_vertex, (std::map<Point, std::size_t>{
                                 {{12, 0, 4}, 5}, {{12, 8, 4}, 5}, {{12, 4, 0}, 5}, {{12, 4, 8}, 5}, {{16, 4, 4}, 4}}));
  EXPECT_EQ(mesh_problem(g, tets), "");
  // M14: the split face attains both ends of the angle range.
  long double lo = 180, hi = 0;
  for (const Tet& t : tets) {
    const std::vector<long double> a = test_dihedral_angles(t);
    lo = std::min(lo, a.front());
    hi = std::max(hi, a.back());
  }
  EXPECT_NEAR(static_cast<double>(lo), 45.0, 1e-9);
  EXPECT_NEAR(static_cast<double>(hi), 120.0, 1e-9);
}

TEST(D3Mesh, BisectedEqualFace) {
  // spec/mesh3d.md M19: the equal face y = 4 between (6,2,2) and (6,6,2) has
  // the node (4,4,2) on an edge: 5 tetrahedra, 3 whole and 2 bisected.
  Graph g(LatticeSize{2, 2, 1, 1});
  ASSERT_TRUE(refine(g, {2, 2, 2}).applied());
  const Tets tets = tetrahedra(g);
  std::size_t whole = 0, bisected = 0;
  for (const Tet& t : tets) {
    if (t[0] != Point{6, 2, 2} || t[1] != Point{6, 6, 2}) continue;
    const auto angles = rounded(test_dihedral_angles(t));
    whole += angles == degrees({60, 60, 60, 60, 90, 90});
    bisected += angles == degrees({45, 60, 60, 90, 90, 90});
  }
  EXPECT_EQ(whole, 3u);
  EXPECT_EQ(bisected, 2u);
  EXPECT_EQ(mesh_problem(g, tets), "");
}

TEST(D3Mesh, UniformLatticesHaveOnly60And90AwayFromTheHull) {
  // spec/mesh3d.md M14: without refinement (and in a uniformly refined
  // lattice) every tetrahedron without a hull vertex is a whole BCC one.
  Graph refined(LatticeSize{2, 2, 2, 1});
  for (const Point c : PointSet(refined.C)) ASSERT_TRUE(refine(refined, c).applied());
  for (const Graph& g : {Graph(LatticeSize{3, 2, 2, 0}), refined}) {
    const Tets tets = tetrahedra(g);
    std::set<long long> inner, hull;
    for (const Tet& t : tets) {
      const bool at_hull = is_hull_vertex(g, t[1]);
      for (const long long a : rounded(test_dihedral_angles(t))) (at_hull ? hull : inner).insert(a);
    }
    EXPECT_EQ(inner, (std::set<long long>{60000000, 90000000}));
    EXPECT_EQ(hull, (std::set<long long>{45000000, 60000000, 90000000}));
    EXPECT_EQ(mesh_problem(g, tets), "");
  }
}

TEST(D3Mesh, RandomStates) {
  // spec/mesh3d.md M3, M10-M14 in every state of random refine/coarsen
  // sequences (refusals included).
  struct Case3 {
    LatticeSize size;
    int steps;
  };
  const Case3 cases[] = {{{1, 1, 1, 3}, 40}, {{2, 1, 1, 2}, 40}, {{2, 2, 1, 2}, 30}, {{2, 2, 2, 1}, 20}};
  std::map<Case, std::size_t> seen;
  for (const Case3& k : cases)
    for (const std::uint64_t seed : {20090303u, 7u}) {
      std::mt19937_64 rng(seed);
      Graph g(k.size);
      std::string trace = lattice_line(k.size);
      for (int step = 0; step < k.steps; ++step) {
        const bool do_refine = std::uniform_int_distribution<int>(0, 99)(rng) < 60;
        const PointSet& from = do_refine ? g.C : g.N;
        auto it = from.begin();
        std::advance(it, static_cast<long>(std::uniform_int_distribution<std::size_t>(0, from.size() - 1)(rng)));
        const Point p = *it;
        trace += std::string(do_refine ? "refine " : "coarsen ") + std::to_string(p.x) + ' ' + std::to_string(p.y) +
                 ' ' + std::to_string(p.z) + '\n';
        if (do_refine)
          refine(g, p);
        else
          coarsen(g, p);
        const Tets tets = tetrahedra(g);
        for (const auto& [c, n] : case_counts(g, tets)) seen[c] += n;
        const std::string why = mesh_problem(g, tets);
        ASSERT_EQ(why, "") << "seed " << seed << ", after:\n" << trace;
      }
    }
  // Every case of the rule occurred (the checks are not vacuous).
  EXPECT_EQ(seen.size(), 4u);
  for (const auto& [c, n] : seen) EXPECT_GT(n, 100u) << static_cast<int>(c);
}

TEST(D3Mesh, AGraphWithoutTheSplitFaceCenterIsRefused) {
  // spec/mesh3d.md M4: the apex of a split face must be a node of the leaf;
  // without it the graph is no reachable state and the extraction throws.
  Graph g(LatticeSize{2, 1, 1, 2});
  ASSERT_TRUE(refine(g, {4, 4, 4}).applied());
  ASSERT_NO_THROW(tetrahedra(g));
  Graph coarse_side = g, fine_side = g;
  coarse_side.neighbors[{12, 4, 4}].erase({8, 4, 4});
  fine_side.neighbors[{6, 2, 2}].erase({8, 4, 4});
  EXPECT_THROW(tetrahedra(coarse_side), std::logic_error);
  EXPECT_THROW(tetrahedra(fine_side), std::logic_error);
}

// The face (axis, side) a tetrahedron (u, v, a, b) was made on: the axis
// of v - u when it has one nonzero coordinate, else (the fine side of a
// split face, M7) the one coordinate v, a and b share.
std::pair<int, bool> face_of(const Tet& t) {
  int axis = -1, nonzero = 0;
  for (int k = 0; k < 3; ++k)
    if (coord(t[1], k) != coord(t[0], k)) ++nonzero, axis = k;
  if (nonzero != 1)
    for (int k = 0; k < 3; ++k)
      if (coord(t[1], k) == coord(t[2], k) && coord(t[1], k) == coord(t[3], k)) axis = k;
  return {axis, coord(t[1], axis) > coord(t[0], axis)};
}

TEST(MeshOrientation, DerivedOrientationAndOrderAreTheExactTestAndSort) {
  // spec/mesh3d.md M24: the extraction orients each tetrahedron from its face's side and
  // orders them from the faces' apexes and the ring's places, with no
  // determinant and no sort. Here M3's way is applied to what it emits
  // (each tetrahedron turned by the sign of its exact determinant, the
  // leaf's list sorted): nothing may change, on graded lattices where every
  // face (axis, side) meets every case of M4.
  std::map<std::tuple<int, bool, Case>, std::size_t> faces;
  std::size_t checked = 0;
  for (const LatticeSize size : {LatticeSize{2, 2, 2, 3}, LatticeSize{3, 2, 1, 3}})
    for (const std::uint64_t seed : {29u, 2009u}) {
      std::mt19937_64 rng(seed);
      Graph g(size);
      for (int step = 0; step < 120; ++step) {
        const bool do_refine = std::uniform_int_distribution<int>(0, 99)(rng) < 80;
        const PointSet& from = do_refine ? g.C : g.N;
        auto it = from.begin();
        std::advance(it, static_cast<long>(std::uniform_int_distribution<std::size_t>(0, from.size() - 1)(rng)));
        if (do_refine)
          refine(g, *it);
        else
          coarsen(g, *it);
      }
      const Tets emitted = tetrahedra(g);
      Tets exact = emitted;
      for (Tet& t : exact) {
        const int o = orientation(t[0], t[1], t[2], t[3]);
        ASSERT_NE(o, 0);
        if (o < 0) std::swap(t[2], t[3]);
      }
      std::sort(exact.begin(), exact.end());
      exact.erase(std::unique(exact.begin(), exact.end()), exact.end());
      ASSERT_EQ(emitted.size(), exact.size()) << "seed " << seed;
      for (std::size_t i = 0; i < emitted.size(); ++i) {
        const auto [axis, high] = face_of(exact[i]);
        ++faces[{axis, high, case_of(g, exact[i])}];
        ASSERT_EQ(emitted[i], exact[i]) << "seed " << seed << ", tetrahedron " << i << " of leaf "
                                        << to_string(exact[i][0]) << ", face axis " << axis
                                        << (high ? " high" : " low");
      }
      checked += emitted.size();
    }
  // Every face (axis, side) occurred in every case it can have.
  for (int axis = 0; axis < 3; ++axis)
    for (const bool high : {false, true})
      for (const Case c : {Case::equal, Case::coarse, Case::fine, Case::hull})
        if (c != Case::equal || high) {  // M3: an equal face is emitted from its lower leaf, as its high face
          EXPECT_GT((faces[{axis, high, c}]), 10u)
              << "axis " << axis << (high ? " high" : " low") << ", case " << static_cast<int>(c);
        }
  EXPECT_GT(checked, 10000u);
}

TEST(D3Mesh, ExactOrientationNear2To62) {
  // spec/mesh3d.md M3: differences of 2^62 need more than 128 bits.
  const std::int64_t big = std::int64_t{1} << 62;
  const Point o{0, 0, 0}, x{big, 0, 0}, y{0, big, 0}, z{0, 0, big};
  EXPECT_EQ(orientation(o, x, y, z), 1);
  EXPECT_EQ(orientation(o, y, x, z), -1);
  EXPECT_EQ(orientation(o, x, y, {big, big, 0}), 0);
  // det = 2^62 - (2^62 - 1) = 1: a sign a double determinant gets wrong.
  EXPECT_EQ(orientation(o, {big, 1, 0}, {big - 1, 1, 0}, {5, 7, 1}), 1);
  EXPECT_EQ(orientation(o, {big - 1, 1, 0}, {big, 1, 0}, {5, 7, 1}), -1);
  EXPECT_THROW(six_volume({o, x, y, z}), std::overflow_error);
  EXPECT_EQ(six_volume({o, {2, 0, 0}, {0, 3, 0}, {0, 0, 4}}), 24);
}

TEST(D3Mesh, LargestLatticeIsTheSmallestScaled) {
  // spec/mesh3d.md M3: lattice 1 1 1 61 (S = 2^62) is lattice 1 1 1 0 scaled
  // by 2^61, and its refined root lattice 1 1 1 1 refined, scaled by 2^60.
  const auto scaled = [](const Tets& tets, std::int64_t f) {
    Tets out;
    for (Tet t : tets) {
      for (Point& p : t) p = {p.x * f, p.y * f, p.z * f};
      out.push_back(t);
    }
    return out;
  };
  Graph big(LatticeSize{1, 1, 1, 61});
  EXPECT_EQ(tetrahedra(big), scaled(tetrahedra(Graph(LatticeSize{1, 1, 1, 0})), std::int64_t{1} << 61));
  const std::int64_t half = std::int64_t{1} << 61;
  ASSERT_TRUE(refine(big, {half, half, half}).applied());
  Graph small(LatticeSize{1, 1, 1, 1});
  ASSERT_TRUE(refine(small, {2, 2, 2}).applied());
  EXPECT_EQ(tetrahedra(big), scaled(tetrahedra(small), std::int64_t{1} << 60));
}

TEST(D3Mesh, IndexMesh) {
  // spec/mesh3d.md M18: 31 nodes, 9 centers, 25 hull vertices (20 children's
  // hull faces and 5 of the coarse leaf).
  Graph g(LatticeSize{2, 1, 1, 2});
  ASSERT_TRUE(refine(g, {4, 4, 4}).applied());
  const Tets tets = tetrahedra(g);
  const TetMesh mesh = index_mesh(g, tets);
  ASSERT_EQ(mesh.vertices.size(), 65u);
  ASSERT_EQ(mesh.kind.size(), 65u);
  EXPECT_TRUE(std::is_sorted(mesh.vertices.begin(), mesh.vertices.end()));
  EXPECT_EQ(std::count(mesh.kind.begin(), mesh.kind.end(), 0), 31);
  EXPECT_EQ(std::count(mesh.kind.begin(), mesh.kind.end(), 1), 9);
  EXPECT_EQ(std::count(mesh.kind.begin(), mesh.kind.end(), 2), 25);
  ASSERT_EQ(mesh.tets.size(), tets.size());
  for (std::size_t i = 0; i < tets.size(); ++i)
    for (std::size_t j = 0; j < 4; ++j) EXPECT_EQ(mesh.vertices[mesh.tets[i][j]], tets[i][j]);
}

// The writers, read back: the positions of every tetrahedron as written.
TetMesh split_face_mesh(Tets* tets) {
  Graph g(LatticeSize{2, 1, 1, 2});
  refine(g, {4, 4, 4});
  *tets = tetrahedra(g);
  return index_mesh(g, *tets);
}

// The text write(out, mesh) makes.
template <class Write>
std::string written(const TetMesh& mesh, Write write) {
  std::ostringstream out;
  write(out, mesh);
  return out.str();
}

std::vector<std::int64_t> numbers(std::istream& in, std::size_t count) {
  std::vector<std::int64_t> out(count);
  for (std::int64_t& v : out) in >> v;
  return out;
}

TEST(D3MeshWriters, VtuReadsBack) {
  Tets tets;
  const TetMesh mesh = split_face_mesh(&tets);
  const std::string text = written(mesh, [](std::ostream& out, const TetMesh& m) { io::write_vtu(out, m); });
  EXPECT_NE(text.find("<Piece NumberOfPoints=\"65\" NumberOfCells=\"168\">"), std::string::npos);
  // The six DataArrays in order: kind, level, points, connectivity, offsets, types.
  std::vector<std::vector<std::int64_t>> arrays;
  const std::size_t sizes[] = {65, 168, 3 * 65, 4 * 168, 168, 168};
  std::size_t pos = 0;
  for (const std::size_t n : sizes) {
    pos = text.find("<DataArray", pos);
    ASSERT_NE(pos, std::string::npos);
    pos = text.find('>', pos) + 1;
    const std::size_t end = text.find("</DataArray>", pos);
    std::istringstream in(text.substr(pos, end - pos));
    arrays.push_back(numbers(in, n));
    std::string rest;
    EXPECT_FALSE(in.fail());
    EXPECT_FALSE(in >> rest) << "more numbers than expected";
    pos = end;
  }
  for (std::size_t i = 0; i < 168; ++i) {
    // The cell data is the level of the leaf v0 (M20): the coarse cube
    // (12, 4, 4) has level 0, the refined cube's children level 1.
    EXPECT_EQ(arrays[1][i], (tets[i][0] == Point{12, 4, 4}) ? 0 : 1);
    EXPECT_EQ(arrays[4][i], static_cast<std::int64_t>(4 * (i + 1)));
    EXPECT_EQ(arrays[5][i], 10);
    for (std::size_t j = 0; j < 4; ++j) {
      const auto v = static_cast<std::size_t>(arrays[3][4 * i + j]);
      EXPECT_EQ((Point{arrays[2][3 * v], arrays[2][3 * v + 1], arrays[2][3 * v + 2]}), tets[i][j]);
    }
  }
  EXPECT_EQ(std::count(arrays[0].begin(), arrays[0].end(), 2), 25);
}

// The sign of det[b - a, c - a, d - a] on lattice points.
int orientation_of(const Point& a, const Point& b, const Point& c, const Point& d) {
  const std::int64_t u[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, v[3] = {c.x - a.x, c.y - a.y, c.z - a.z},
                     w[3] = {d.x - a.x, d.y - a.y, d.z - a.z};
  const std::int64_t det =
      u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
  return (det > 0) - (det < 0);
}

// `tri` is a face of exactly one of `tets`, and that tetrahedron's fourth
// vertex lies behind it (the triangle faces outward).
void expect_outward_boundary(const Tets& tets, const std::array<Point, 3>& tri) {
  int owners = 0;
  for (const Tet& t : tets) {
    int shared = 0;
    const Point* other = nullptr;
    for (const Point& p : t) {
      if (p == tri[0] || p == tri[1] || p == tri[2])
        ++shared;
      else
        other = &p;
    }
    if (shared != 3) continue;
    ++owners;
    EXPECT_LT(orientation_of(tri[0], tri[1], tri[2], *other), 0) << "a boundary triangle faces inward";
  }
  EXPECT_EQ(owners, 1);
}

// M21: the physical groups, entities, nodes, the tetrahedra in their order
// and the boundary triangles (104 on the split state, mesh3d.md M18's
// boundary_triangles) facing outward.
TEST(D3MeshWriters, MshReadsBack) {
  Tets tets;
  const TetMesh mesh = split_face_mesh(&tets);
  std::istringstream in(written(mesh, [](std::ostream& out, const TetMesh& m) { io::write_msh(out, m); }));
  std::string word;
  in >> word;
  EXPECT_EQ(word, "$MeshFormat");
  double version = 0;
  int file_type = -1, data_size = 0;
  in >> version >> file_type >> data_size >> word;
  EXPECT_EQ(version, 4.1);
  EXPECT_EQ(file_type, 0);
  EXPECT_EQ(data_size, 8);
  EXPECT_EQ(word, "$EndMeshFormat");
  std::string line;
  std::getline(in >> std::ws, line);
  EXPECT_EQ(line, "$PhysicalNames");
  for (const char* expected : {"2", "3 1 \"component_1\"", "2 2 \"boundary\"", "$EndPhysicalNames", "$Entities"}) {
    std::getline(in, line);
    EXPECT_EQ(line, expected);
  }
  // No points or curves; surface 1 (the boundary, physical 2), volume 1
  // (physical 1, bounded by surface 1), both with the box [0,16]x[0,8]x[0,8].
  EXPECT_EQ(numbers(in, 4), (std::vector<std::int64_t>{0, 0, 1, 1}));
  EXPECT_EQ(numbers(in, 10), (std::vector<std::int64_t>{1, 0, 0, 0, 16, 8, 8, 1, 2, 0}));
  EXPECT_EQ(numbers(in, 11), (std::vector<std::int64_t>{1, 0, 0, 0, 16, 8, 8, 1, 1, 1, 1}));
  in >> word;
  EXPECT_EQ(word, "$EndEntities");
  in >> word;
  EXPECT_EQ(word, "$Nodes");
  EXPECT_EQ(numbers(in, 8), (std::vector<std::int64_t>{1, 65, 1, 65, 3, 1, 0, 65}));
  const std::vector<std::int64_t> tags = numbers(in, 65);
  for (std::size_t i = 0; i < 65; ++i) EXPECT_EQ(tags[i], static_cast<std::int64_t>(i + 1));
  const std::vector<std::int64_t> xyz = numbers(in, 3 * 65);
  const auto point = [&](std::int64_t tag) {
    const auto v = static_cast<std::size_t>(tag - 1);
    return Point{xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
  };
  in >> word;
  EXPECT_EQ(word, "$EndNodes");
  in >> word;
  EXPECT_EQ(word, "$Elements");
  EXPECT_EQ(numbers(in, 8), (std::vector<std::int64_t>{2, 272, 1, 272, 3, 1, 4, 168}));
  for (std::size_t i = 0; i < 168; ++i) {
    const std::vector<std::int64_t> e = numbers(in, 5);
    EXPECT_EQ(e[0], static_cast<std::int64_t>(i + 1));
    for (std::size_t j = 0; j < 4; ++j) EXPECT_EQ(point(e[j + 1]), tets[i][j]);
  }
  EXPECT_EQ(numbers(in, 4), (std::vector<std::int64_t>{2, 1, 2, 104}));
  for (std::size_t i = 0; i < 104; ++i) {
    const std::vector<std::int64_t> e = numbers(in, 4);
    EXPECT_EQ(e[0], static_cast<std::int64_t>(168 + i + 1));
    expect_outward_boundary(tets, {point(e[1]), point(e[2]), point(e[3])});
  }
  in >> word;
  EXPECT_EQ(word, "$EndElements");
  EXPECT_FALSE(in.fail());
  EXPECT_FALSE(in >> word) << "text after $EndElements";
}

// Meshes the tests build by hand: an empty one (the writers' counts and
// entity blocks of zero, mesh_quality of nothing), a TetMesh without levels
// (Medit writes reference 0), and a tetrahedron whose v0 is not a center
// (index_mesh gives it level -1). spec/mesh3d.md M20-M22, §6.
TEST(D3MeshWriters, EmptyAndHandBuiltMeshes) {
  const MeshQuality q = mesh_quality({});
  EXPECT_EQ(q.tetrahedra, 0u);
  EXPECT_EQ(q.vertices, 0u);
  EXPECT_EQ(q.boundary_triangles, 0u);
  EXPECT_EQ(q.min_dihedral, 0.0);
  EXPECT_EQ(q.max_dihedral, 0.0);
  const TetMesh empty;
  std::ostringstream msh;
  io::write_msh(msh, empty);
  EXPECT_EQ(msh.str(),
            "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n0\n$EndPhysicalNames\n$Entities\n0 0 0 0\n"
            "$EndEntities\n$Nodes\n0 0 0 0\n$EndNodes\n$Elements\n0 0 0 0\n$EndElements\n");
  // One cube (lattice 1 1 1 0): a tetrahedron listed from a corner first.
  const Graph g(LatticeSize{1, 1, 1, 0});
  const Tet t{Point{0, 0, 0}, Point{2, 0, 0}, Point{0, 2, 0}, Point{0, 0, 2}};
  const TetMesh m = index_mesh(g, {t});
  ASSERT_EQ(m.level.size(), 1u);
  EXPECT_EQ(m.level[0], -1);
  TetMesh no_levels = m;
  no_levels.level.clear();
  std::ostringstream medit;
  io::write_medit(medit, no_levels);
  // Vertices sorted by position: (0,0,0) 1, (0,0,2) 2, (0,2,0) 3, (2,0,0) 4.
  EXPECT_NE(medit.str().find("Tetrahedra\n1\n1 4 3 2 0\n"), std::string::npos) << medit.str();
}

TEST(D3MeshWriters, MeditReadsBack) {
  Tets tets;
  const TetMesh mesh = split_face_mesh(&tets);
  std::istringstream in(written(mesh, [](std::ostream& out, const TetMesh& m) { io::write_medit(out, m); }));
  std::string a, b;
  in >> a >> b;
  EXPECT_EQ(a + ' ' + b, "MeshVersionFormatted 2");
  in >> a >> b;
  EXPECT_EQ(a + ' ' + b, "Dimension 3");
  in >> a;
  EXPECT_EQ(a, "Vertices");
  EXPECT_EQ(numbers(in, 1).front(), 65);
  const std::vector<std::int64_t> v = numbers(in, 4 * 65);
  in >> a;
  EXPECT_EQ(a, "Tetrahedra");
  EXPECT_EQ(numbers(in, 1).front(), 168);
  for (std::size_t i = 0; i < 168; ++i) {
    const std::vector<std::int64_t> e = numbers(in, 5);
    // The reference is the level of the tetrahedron's leaf v0 (M22): in the
    // split state the coarse cube (12, 4, 4) has level 0, its neighbour's
    // children level 1.
    EXPECT_EQ(e[4], (tets[i][0] == Point{12, 4, 4}) ? 0 : 1);
    for (std::size_t j = 0; j < 4; ++j) {
      const auto k = static_cast<std::size_t>(e[j] - 1);
      EXPECT_EQ((Point{v[4 * k], v[4 * k + 1], v[4 * k + 2]}), tets[i][j]);
      EXPECT_EQ(v[4 * k + 3], static_cast<std::int64_t>(mesh.kind[k]));
    }
  }
  // M22: the boundary triangles, outward, each with its component (1).
  in >> a;
  EXPECT_EQ(a, "Triangles");
  EXPECT_EQ(numbers(in, 1).front(), 104);
  for (std::size_t i = 0; i < 104; ++i) {
    const std::vector<std::int64_t> e = numbers(in, 4);
    std::array<Point, 3> tri;
    for (std::size_t j = 0; j < 3; ++j) {
      const auto k = static_cast<std::size_t>(e[j] - 1);
      tri[j] = Point{v[4 * k], v[4 * k + 1], v[4 * k + 2]};
    }
    expect_outward_boundary(tets, tri);
    EXPECT_EQ(e[3], 1);
  }
  in >> a;
  EXPECT_EQ(a, "End");
  EXPECT_FALSE(in.fail());
  EXPECT_FALSE(in >> a) << "text after End";
}

}  // namespace
}  // namespace bccmis::d3
