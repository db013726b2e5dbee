// Closed triangle meshes as shapes (spec/stuffing.md §1): the OFF, OBJ and
// STL files read (by bccmis/io/), the checks that make a triangle soup a
// closed, manifold, consistently oriented, self-intersection free surface,
// and the Shape over it. The only translation unit of bccmis::stuff that
// includes CGAL.
#include "bccmis/stuff/surface.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <sstream>
#include <string_view>
#include <thread>
#include <unordered_map>
#include <utility>

#include "bccmis/io/obj.h"
#include "bccmis/io/off.h"
#include "bccmis/io/read_error.h"
#include "bccmis/io/stl.h"
#include "bccmis/io/triangle_soup.h"
#include "bccmis/soup/winding_number.h"
#include "bccmis/stuff/normalisation.h"
#include "bccmis/stuff/soup_report.h"

namespace bccmis::stuff {
namespace {

using K = CGAL::Epick;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
using Side = CGAL::Side_of_triangle_mesh<Mesh, K, CGAL::Default, Tree>;
namespace PMP = CGAL::Polygon_mesh_processing;

using Tri = std::array<std::uint32_t, 3>;

using Soup = io::TriangleSoup;

std::string basename_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::uint64_t edge_key(std::uint32_t u, std::uint32_t w) {
  return static_cast<std::uint64_t>(std::min(u, w)) << 32 | std::max(u, w);
}

/// The edge-connected components of triangles (through every shared edge).
struct Components {
  std::size_t count = 0;
  std::vector<std::size_t> of;
};
Components edge_components(const std::vector<Tri>& T) {
  std::vector<std::size_t> parent(T.size());
  for (std::size_t i = 0; i < T.size(); ++i) parent[i] = i;
  const auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::unordered_map<std::uint64_t, std::size_t> first;
  for (std::size_t t = 0; t < T.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k) {
      const auto [it, fresh] = first.try_emplace(edge_key(T[t][k], T[t][(k + 1) % 3]), t);
      if (!fresh) parent[find(t)] = find(it->second);
    }
  Components c;
  c.of.assign(T.size(), 0);
  std::vector<std::size_t> label(T.size(), SIZE_MAX);
  for (std::size_t t = 0; t < T.size(); ++t) {
    const std::size_t r = find(t);
    if (label[r] == SIZE_MAX) label[r] = c.count++;
    c.of[t] = label[r];
  }
  return c;
}

/// S27's view of a soup's surface: its edge-connected components and the
/// smallest thinnest extent of their bounding boxes.
SurfaceComponents components_of(const Soup& s) {
  const Components c = edge_components(s.triangles);
  std::vector<Bounds> box(c.count, Bounds{{HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}});
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    for (const std::uint32_t v : s.triangles[t])
      for (std::size_t k = 0; k < 3; ++k) {
        box[c.of[t]].lo[k] = std::min(box[c.of[t]].lo[k], s.vertices[v][k]);
        box[c.of[t]].hi[k] = std::max(box[c.of[t]].hi[k], s.vertices[v][k]);
      }
  SurfaceComponents out{c.count, HUGE_VAL};
  for (const Bounds& b : box)
    for (std::size_t k = 0; k < 3; ++k) out.thinnest = std::min(out.thinnest, b.hi[k] - b.lo[k]);
  return out;
}

// ---------------------------------------------------------------------------
// The checks.

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

class Checker {
 public:
  Checker(const Soup& s, const std::string& name) : s_(s), name_(name) {}

  std::string face(std::size_t t) const {
    std::string r = "face " + std::to_string(s_.face[t]);
    if (s_.line[t] != 0) r += " on line " + std::to_string(s_.line[t]);
    return r;
  }
  std::string vertex(std::uint32_t v) const { return std::to_string(static_cast<std::uint64_t>(v) + s_.vertex_base); }
  [[noreturn]] void fail(const std::string& what) const { throw ShapeError(name_ + ": " + what); }

  /// The refusals of both modes (S21): no faces, a coordinate not finite, an
  /// index out of range.
  void basics() const {
    const auto& V = s_.vertices;
    const auto& T = s_.triangles;
    if (T.empty()) fail("empty mesh (no faces)");
    for (std::size_t i = 0; i < V.size(); ++i)
      for (double x : V[i])
        if (!std::isfinite(x)) fail("vertex " + vertex(static_cast<std::uint32_t>(i)) + " has a coordinate not finite");
    for (std::size_t t = 0; t < T.size(); ++t)
      for (auto v : T[t])
        if (v >= V.size())
          fail(face(t) + ": vertex index " + vertex(v) + " out of range (" + std::to_string(V.size()) + " vertices)");
  }

  void run() const {
    const auto& T = s_.triangles;
    basics();
    for (std::size_t t = 0; t < T.size(); ++t) {
      const auto [a, b, c] = T[t];
      if (a == b || b == c || a == c)
        fail(face(t) + " is degenerate: vertex " + vertex(a == b || a == c ? a : b) + " repeated");
      if (CGAL::collinear(point(a), point(b), point(c)))
        fail(face(t) + " is degenerate: zero area (vertices " + vertex(a) + ", " + vertex(b) + " and " + vertex(c) +
             " are collinear)");
    }
    // Edges: the faces on each, with their direction.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> edges;
    for (std::size_t t = 0; t < T.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const auto u = T[t][static_cast<std::size_t>(k)], w = T[t][static_cast<std::size_t>((k + 1) % 3)];
        edges[{std::min(u, w), std::max(u, w)}].push_back(t);
      }
    // Reported in the order of the faces: the first face with a bad edge.
    std::optional<std::pair<std::uint32_t, std::uint32_t>> border;
    std::size_t borders = 0;
    for (std::size_t t = 0; t < T.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const auto u = T[t][static_cast<std::size_t>(k)], w = T[t][static_cast<std::size_t>((k + 1) % 3)];
        const auto& on = edges.at({std::min(u, w), std::max(u, w)});
        if (on.size() > 2) {
          std::string list;
          for (std::size_t i = 0; i < on.size(); ++i)
            list += (i == 0 ? "" : i + 1 == on.size() ? " and " : ", ") + face(on[i]);
          fail("non-manifold edge between vertex " + vertex(u) + " and vertex " + vertex(w) + ": " +
               std::to_string(on.size()) + " faces (" + list + ")");
        }
        if (on.size() == 1 && !border) border = {u, w};
      }
    for (const auto& [e, on] : edges) borders += on.size() == 1;
    if (border)
      fail("open mesh: " + std::to_string(borders) + " border edge" + (borders == 1 ? "" : "s") + ", one from vertex " +
           vertex(border->first) + " to vertex " + vertex(border->second));
    for (std::size_t t = 0; t < T.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const auto u = T[t][static_cast<std::size_t>(k)], w = T[t][static_cast<std::size_t>((k + 1) % 3)];
        const auto& on = edges.at({std::min(u, w), std::max(u, w)});
        const std::size_t other = on[0] == t ? on[1] : on[0];
        if (other > t && runs(other, u, w))
          fail("inconsistent orientation: " + face(t) + " and " + face(other) + " both run from vertex " + vertex(u) +
               " to vertex " + vertex(w));
      }
    check_vertex_fans(edges);
  }

 private:
  Point point(std::uint32_t v) const { return {s_.vertices[v][0], s_.vertices[v][1], s_.vertices[v][2]}; }
  bool runs(std::size_t t, std::uint32_t u, std::uint32_t w) const {
    for (int k = 0; k < 3; ++k)
      if (s_.triangles[t][static_cast<std::size_t>(k)] == u &&
          s_.triangles[t][static_cast<std::size_t>((k + 1) % 3)] == w)
        return true;
    return false;
  }
  /// Every vertex of a closed, edge-manifold surface must have its faces in
  /// one cycle around it; two or more cycles pinch the surface there.
  void check_vertex_fans(
      const std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>>& edges) const {
    const auto& T = s_.triangles;
    std::vector<std::vector<std::size_t>> around(s_.vertices.size());
    for (std::size_t t = 0; t < T.size(); ++t)
      for (auto v : T[t]) around[v].push_back(t);
    std::vector<char> seen(T.size(), 0);
    for (std::uint32_t v = 0; v < around.size(); ++v) {
      const auto& fan = around[v];
      if (fan.empty()) continue;
      // Walk from the first face across the edges at v; a face not reached
      // belongs to another fan.
      std::vector<std::size_t> stack{fan[0]};
      seen[fan[0]] = 1;
      while (!stack.empty()) {
        const std::size_t t = stack.back();
        stack.pop_back();
        for (auto w : T[t]) {
          if (w == v) continue;
          for (std::size_t o : edges.at({std::min(v, w), std::max(v, w)}))
            if (!seen[o]) {
              seen[o] = 1;
              stack.push_back(o);
            }
        }
      }
      const auto other = std::find_if(fan.begin(), fan.end(), [&](std::size_t t) { return !seen[t]; });
      if (other != fan.end())
        fail("non-manifold vertex " + vertex(v) + ": its faces form more than one fan (" + face(fan[0]) + " and " +
             face(*other) + " meet only at it)");
      for (std::size_t t : fan) seen[t] = 0;
    }
  }

  const Soup& s_;
  const std::string& name_;
};

// ---------------------------------------------------------------------------
// The shape.

// n points uniform on the triangles by area (area_sum: the running sums of
// their areas), drawn from `seed`.
/// The triangles as arrays of coordinates (Shape::surface_triangles).
std::vector<std::array<Vec3, 3>> to_vec3(const std::vector<std::array<Point, 3>>& triangles) {
  std::vector<std::array<Vec3, 3>> out;
  out.reserve(triangles.size());
  for (const auto& t : triangles) {
    std::array<Vec3, 3>& o = out.emplace_back();
    for (std::size_t i = 0; i < 3; ++i) o[i] = {t[i].x(), t[i].y(), t[i].z()};
  }
  return out;
}

std::vector<Vec3> sample_triangles(const std::vector<std::array<Point, 3>>& triangles,
                                   const std::vector<double>& area_sum, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> out;
  out.reserve(n);
  const double total = area_sum.back();
  for (std::size_t i = 0; i < n; ++i) {
    const double pick = u(rng) * total;
    const auto it = std::upper_bound(area_sum.begin(), area_sum.end(), pick);
    const std::size_t t = std::min<std::size_t>(static_cast<std::size_t>(it - area_sum.begin()), area_sum.size() - 1);
    // Uniform on the triangle: sqrt of one variable, the other linear.
    const double r = std::sqrt(u(rng)), w = u(rng);
    const auto& [a, b, c] = triangles[t];
    const double ca = 1 - r, cb = r * (1 - w), cc = r * w;
    out.push_back({ca * a.x() + cb * b.x() + cc * c.x(), ca * a.y() + cb * b.y() + cc * c.y(),
                   ca * a.z() + cb * b.z() + cc * c.z()});
  }
  return out;
}

class MeshShape final : public Shape {
 public:
  MeshShape(const Soup& s, const std::string& name) : name_(basename_of(name)), surface_components_(components_of(s)) {
    std::vector<Mesh::Vertex_index> vs;
    vs.reserve(s.vertices.size());
    for (const auto& p : s.vertices) vs.push_back(mesh_.add_vertex(Point(p[0], p[1], p[2])));
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
      const auto& tri = s.triangles[t];
      const auto f = mesh_.add_face(vs[tri[0]], vs[tri[1]], vs[tri[2]]);
      if (f == Mesh::null_face()) throw ShapeError(name + ": face " + std::to_string(s.face[t]) + " does not fit");
    }
    // Unused vertices would sit outside every face: drop them.
    for (auto v : mesh_.vertices())
      if (mesh_.is_isolated(v)) mesh_.remove_vertex(v);
    mesh_.collect_garbage();

    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> crossing_faces;
    PMP::self_intersections(mesh_, std::back_inserter(crossing_faces));
    if (!crossing_faces.empty()) {
      // Report the pair of smallest face numbers, so the message is the same
      // whatever order CGAL finds them in. Face indices are the order of
      // insertion, which is the order of the soup's triangles.
      std::pair<std::size_t, std::size_t> best{SIZE_MAX, SIZE_MAX};
      for (const auto& [f, g] : crossing_faces) {
        std::size_t a = s.face[f.idx()], b = s.face[g.idx()];
        if (a > b) std::swap(a, b);
        best = std::min(best, std::pair{a, b});
      }
      if (best.first == best.second)
        throw ShapeError(name + ": self-intersecting: the triangles of face " + std::to_string(best.first) +
                         ", a polygon fanned from its first corner, intersect (face " + std::to_string(best.first) +
                         " is not convex or not flat)");
      throw ShapeError(name + ": self-intersecting (face " + std::to_string(best.first) + " and face " +
                       std::to_string(best.second) + ")");
    }
    PMP::orient_to_bound_a_volume(mesh_);

    tree_.insert(faces(mesh_).first, faces(mesh_).second, mesh_);
    tree_.build();
    tree_.accelerate_distance_queries();
    side_.emplace(tree_);
    const CGAL::Bbox_3 box = PMP::bbox(mesh_);
    bounds_ = {{box.xmin(), box.ymin(), box.zmin()}, {box.xmax(), box.ymax(), box.zmax()}};
    // The volume: signed tetrahedra from the lowest corner of the box to each
    // face, summed, divided by 6 once (exact for small integer coordinates).
    const Point o(box.xmin(), box.ymin(), box.zmin());
    double six_volume = 0;
    for (auto f : mesh_.faces()) {
      const auto h = mesh_.halfedge(f);
      const Point& a = mesh_.point(mesh_.source(h));
      const Point& b = mesh_.point(mesh_.target(h));
      const Point& c = mesh_.point(mesh_.target(mesh_.next(h)));
      triangles_.push_back({a, b, c});
      six_volume += CGAL::determinant(a - o, b - o, c - o);
      area_sum_.push_back((area_sum_.empty() ? 0.0 : area_sum_.back()) +
                          std::sqrt(K::Triangle_3(a, b, c).squared_area()));
    }
    volume_ = six_volume / 6;
  }

  double signed_distance(const Vec3& p) const override {
    const Point q(p[0], p[1], p[2]);
    const CGAL::Bounded_side side = (*side_)(q);
    if (side == CGAL::ON_BOUNDARY) return 0;
    const double d = std::sqrt(tree_.squared_distance(q));
    return side == CGAL::ON_BOUNDED_SIDE ? -d : d;
  }

  // The side query alone (a ray cast, exact), without the distance.
  int side(const Vec3& p) const override {
    const CGAL::Bounded_side s = (*side_)(Point(p[0], p[1], p[2]));
    return s == CGAL::ON_BOUNDED_SIDE ? -1 : s == CGAL::ON_BOUNDARY ? 0 : 1;
  }

  // Without the side query (a ray cast): the distance alone.
  double distance(const Vec3& p) const override { return std::sqrt(tree_.squared_distance(Point(p[0], p[1], p[2]))); }
  bool distance_is_lipschitz() const override { return true; }  // S37: the distance to the triangles
  // S39: the tree's closest point; its squared distance as the tree computes it.
  Nearest nearest(const Vec3& p) const override {
    const Point q(p[0], p[1], p[2]);
    const Point c = tree_.closest_point(q);
    return {std::sqrt(Tree::AABB_traits().squared_distance_object()(q, c)), Vec3{c.x(), c.y(), c.z()}};
  }

  double crossing(const Vec3& a, const Vec3& b) const override {
    if (a == b) return 0;
    const Point pa(a[0], a[1], a[2]), qb(b[0], b[1], b[2]);
    const K::Segment_3 seg(pa, qb);
    std::vector<Tree::Intersection_and_primitive_id<K::Segment_3>::Type> hits;
    tree_.all_intersections(seg, std::back_inserter(hits));
    const K::Vector_3 d = qb - pa;
    const double dd = d.squared_length();
    double best = std::numeric_limits<double>::infinity();
    auto param = [&](const Point& p) { return std::clamp(((p - pa) * d) / dd, 0.0, 1.0); };
    for (const auto& hit : hits) {
      if (const Point* p = boost::get<Point>(&hit.first))
        best = std::min(best, param(*p));
      else if (const K::Segment_3* sg = boost::get<K::Segment_3>(&hit.first))
        best = std::min({best, param(sg->source()), param(sg->target())});
    }
    if (std::isfinite(best)) return best;
    return bisect_crossing(*this, a, b);
  }

  Bounds bounds() const override { return bounds_; }
  double volume() const override { return volume_; }

  std::vector<Vec3> sample_surface(std::size_t n, std::uint64_t seed) const override {
    return sample_triangles(triangles_, area_sum_, n, seed);
  }

  std::string describe() const override {
    return "mesh " + name_ + ": " + std::to_string(triangles_.size()) + " triangles";
  }
  std::optional<SurfaceComponents> surface_components() const override { return surface_components_; }
  std::vector<std::array<Vec3, 3>> surface_triangles() const override { return to_vec3(triangles_); }

  const SoupReport* soup_report() const override { return report_ ? &*report_ : nullptr; }
  /// The default path's report of a clean file (S21): its notes filled here.
  void set_report(SoupReport r, const Soup& s) {
    // Faces orient_to_bound_a_volume reversed: not a rotation of the input's corners.
    std::vector<char> reversed(s.triangles.size(), 0);
    for (std::size_t t = 0; t < s.triangles.size() && t < triangles_.size(); ++t) {
      const auto& [a, b, c] = triangles_[t];
      const auto& in = s.triangles[t];
      const Point p(s.vertices[in[0]][0], s.vertices[in[0]][1], s.vertices[in[0]][2]);
      const Point q(s.vertices[in[1]][0], s.vertices[in[1]][1], s.vertices[in[1]][2]);
      reversed[t] = !((a == p && b == q) || (b == p && c == q) || (c == p && a == q));
    }
    const auto comp = edge_components(s.triangles);
    r.components = comp.count;
    std::vector<char> inward(comp.count, 0);
    for (std::size_t t = 0; t < reversed.size(); ++t)
      if (reversed[t]) inward[comp.of[t]] = 1;
    r.inward_components = static_cast<std::size_t>(std::count(inward.begin(), inward.end(), 1));
    report_ = std::move(r);
  }

 private:
  std::optional<SoupReport> report_;
  std::string name_;
  SurfaceComponents surface_components_;
  Mesh mesh_;
  Tree tree_;
  std::optional<Side> side_;
  double volume_ = 0;
  Bounds bounds_;
  std::vector<std::array<Point, 3>> triangles_;
  std::vector<double> area_sum_;
};

// ---------------------------------------------------------------------------
// Triangle soups (S20-S23): the inspection that counts every flaw, the
// repairs, and the shape of the solid {w >= 1/2}.

/// A soup inspected and repaired (S21, S22): the report, the triangles kept
/// (oriented), the input face of each, and the net boundary of the kept
/// triangles as directed edges, repeated by multiplicity.
struct Repaired {
  SoupReport report;
  std::vector<Tri> tris;
  std::vector<std::size_t> face;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> boundary;
};

/// Whether the triangles t1, t2 (indices into V, not degenerate, not the
/// same three vertices) meet other than in the vertices or the edge they
/// share, after PMP::self_intersections' rules.
bool faces_meet(const std::vector<Vec3>& V, const Tri& t1, const Tri& t2) {
  const auto P = [&](std::uint32_t v) { return Point(V[v][0], V[v][1], V[v][2]); };
  std::array<int, 3> in2{-1, -1, -1};  // for each corner of t1, its corner in t2
  int shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (t1[static_cast<std::size_t>(i)] == t2[static_cast<std::size_t>(j)])
        in2[static_cast<std::size_t>(i)] = j, ++shared;
  const K::Triangle_3 T1(P(t1[0]), P(t1[1]), P(t1[2])), T2(P(t2[0]), P(t2[1]), P(t2[2]));
  if (shared == 0) return CGAL::do_intersect(T1, T2);
  if (shared == 1) {
    std::size_t i = 0;
    while (in2[i] < 0) ++i;
    const auto j = static_cast<std::size_t>(in2[i]);
    const K::Segment_3 opp1(P(t1[(i + 1) % 3]), P(t1[(i + 2) % 3])), opp2(P(t2[(j + 1) % 3]), P(t2[(j + 2) % 3]));
    return CGAL::do_intersect(opp1, T2) || CGAL::do_intersect(opp2, T1);
  }
  // A shared edge pq: they overlap when coplanar with the third corners on the same side.
  std::size_t i = 0, j = 0;
  while (in2[i] >= 0) ++i;  // the corner of t1 not in t2
  for (std::size_t k = 0; k < 3; ++k)
    if (t2[k] != t1[0] && t2[k] != t1[1] && t2[k] != t1[2]) j = k;
  const Point p = P(t1[(i + 1) % 3]), q = P(t1[(i + 2) % 3]), r = P(t1[i]), x = P(t2[j]);
  return CGAL::coplanar(p, q, r, x) && CGAL::coplanar_orientation(p, q, r, x) == CGAL::POSITIVE;
}

/// STL facet normals not finite, zero, or against the vertex order (S21).
SoupFlaw bad_normals_of(const Soup& s) {
  SoupFlaw f;
  const auto P = [&](std::uint32_t v) { return Point(s.vertices[v][0], s.vertices[v][1], s.vertices[v][2]); };
  for (std::size_t t = 0; t < s.normals.size() && t < s.triangles.size(); ++t) {
    const auto& n = s.normals[t];
    const auto& [a, b, c] = s.triangles[t];
    const K::Vector_3 m = CGAL::cross_product(P(b) - P(a), P(c) - P(a));
    const bool finite = std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]);
    if (!finite || (n[0] == 0 && n[1] == 0 && n[2] == 0) || m * K::Vector_3(n[0], n[1], n[2]) < 0) {
      if (f.first.size() < SoupReport::kListed) f.first.push_back({s.face[t]});
      ++f.count;
    }
  }
  return f;
}

Repaired inspect(const Soup& s, const std::string& name) {
  const auto& V = s.vertices;
  const auto& T = s.triangles;
  Repaired out;
  SoupReport& r = out.report;
  r.file = name;
  r.faces = T.size();
  std::array<std::vector<std::vector<std::size_t>>, SoupReport::kKinds> found;
  const auto add = [&](SoupReport::Kind k, std::vector<std::size_t> faces) {
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    found[k].push_back(std::move(faces));
  };
  const auto P = [&](std::uint32_t v) { return Point(V[v][0], V[v][1], V[v][2]); };

  // Degenerate faces, then the same three vertices: back-to-back pairs
  // dropped, duplicates after the first dropped.
  std::vector<char> keep(T.size(), 1);
  std::map<Tri, std::vector<std::size_t>> same;
  for (std::size_t t = 0; t < T.size(); ++t) {
    const auto [a, b, c] = T[t];
    if (a == b || b == c || a == c || CGAL::collinear(P(a), P(b), P(c))) {
      keep[t] = 0;
      add(SoupReport::degenerate_faces, {s.face[t]});
      continue;
    }
    Tri key = T[t];
    std::sort(key.begin(), key.end());
    same[key].push_back(t);
  }
  for (const auto& [key, ts] : same) {
    if (ts.size() < 2) continue;
    // Parity against the sorted corners: a rotation of them, or not.
    std::vector<std::size_t> plus, minus;
    for (std::size_t t : ts) {
      const Tri& x = T[t];
      const bool even = (x[0] == key[0] && x[1] == key[1]) || (x[1] == key[0] && x[2] == key[1]) ||
                        (x[2] == key[0] && x[0] == key[1]);
      (even ? plus : minus).push_back(t);
    }
    const std::size_t pairs = std::min(plus.size(), minus.size());
    for (std::size_t i = 0; i < pairs; ++i) {
      keep[plus[i]] = keep[minus[i]] = 0;
      add(SoupReport::back_to_back_faces, {s.face[plus[i]], s.face[minus[i]]});
    }
    const auto& rest = plus.size() > pairs ? plus : minus;
    for (std::size_t i = pairs + 1; i < rest.size(); ++i) {
      keep[rest[i]] = 0;
      add(SoupReport::duplicate_faces, {s.face[rest[pairs]], s.face[rest[i]]});
    }
  }
  std::vector<std::size_t> kept;  // indices into T, in order
  for (std::size_t t = 0; t < T.size(); ++t)
    if (keep[t]) kept.push_back(t);
  r.dropped_faces = T.size() - kept.size();

  // Edges of the kept faces: k (index into kept) on each.
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> edges;
  for (std::size_t k = 0; k < kept.size(); ++k)
    for (std::size_t i = 0; i < 3; ++i) edges[edge_key(T[kept[k]][i], T[kept[k]][(i + 1) % 3])].push_back(k);
  const auto runs = [&](std::size_t t, std::uint32_t u, std::uint32_t w) {
    for (std::size_t i = 0; i < 3; ++i)
      if (T[t][i] == u && T[t][(i + 1) % 3] == w) return true;
    return false;
  };
  for (const auto& [e, on] : edges) {
    std::vector<std::size_t> faces;
    for (std::size_t k : on) faces.push_back(s.face[kept[k]]);
    if (on.size() == 1) add(SoupReport::border_edges, faces);
    if (on.size() > 2) add(SoupReport::nonmanifold_edges, faces);
    if (on.size() == 2) {
      const auto u = static_cast<std::uint32_t>(e >> 32), w = static_cast<std::uint32_t>(e);
      if (runs(kept[on[0]], u, w) == runs(kept[on[1]], u, w)) add(SoupReport::inconsistent_edges, faces);
    }
  }
  // Non-manifold vertices: the kept faces at a vertex in more than one fan.
  {
    std::vector<std::vector<std::size_t>> around(V.size());
    for (std::size_t k = 0; k < kept.size(); ++k)
      for (auto v : T[kept[k]]) around[v].push_back(k);
    std::vector<char> seen(kept.size(), 0);
    for (std::uint32_t v = 0; v < around.size(); ++v) {
      const auto& fan = around[v];
      if (fan.empty()) continue;
      std::vector<std::size_t> stack{fan[0]};
      seen[fan[0]] = 1;
      while (!stack.empty()) {
        const std::size_t k = stack.back();
        stack.pop_back();
        for (auto w : T[kept[k]]) {
          if (w == v) continue;
          for (std::size_t o : edges.at(edge_key(v, w)))
            if (!seen[o]) seen[o] = 1, stack.push_back(o);
        }
      }
      const auto other = std::find_if(fan.begin(), fan.end(), [&](std::size_t k) { return !seen[k]; });
      if (other != fan.end()) add(SoupReport::nonmanifold_vertices, {s.face[kept[fan[0]]], s.face[kept[*other]]});
      for (std::size_t k : fan) seen[k] = 0;
    }
  }

  // S22: orientation made consistent across manifold edges (breadth first
  // from each component's first face), the larger class keeping its way round.
  std::vector<char> flip(kept.size(), 0);
  std::vector<std::size_t> comp(kept.size(), SIZE_MAX);
  std::vector<std::vector<std::size_t>> members;
  for (std::size_t start = 0; start < kept.size(); ++start) {
    if (comp[start] != SIZE_MAX) continue;
    const std::size_t c = members.size();
    members.emplace_back();
    std::vector<std::size_t> queue{start};
    comp[start] = c;
    for (std::size_t qi = 0; qi < queue.size(); ++qi) {
      const std::size_t k = queue[qi];
      members[c].push_back(k);
      const Tri& t = T[kept[k]];
      for (std::size_t i = 0; i < 3; ++i) {
        // The edge as face k runs it after its flip.
        std::uint32_t u = t[i], w = t[(i + 1) % 3];
        if (flip[k]) std::swap(u, w);
        const auto& on = edges.at(edge_key(u, w));
        if (on.size() != 2) continue;
        const std::size_t j = on[0] == k ? on[1] : on[0];
        if (comp[j] != SIZE_MAX) continue;
        comp[j] = c;
        flip[j] = runs(kept[j], u, w) ? 1 : 0;
        queue.push_back(j);
      }
    }
    std::size_t flipped = 0;
    for (std::size_t k : members[c]) flipped += flip[k];
    if (2 * flipped > members[c].size()) {
      for (std::size_t k : members[c]) flip[k] = !flip[k];
      flipped = members[c].size() - flipped;
    }
    r.flipped_faces += flipped;
  }
  r.components = members.size();
  const auto oriented = [&](std::size_t k) {
    Tri t = T[kept[k]];
    if (flip[k]) std::swap(t[1], t[2]);
    return t;
  };
  // Then each component bounds positive volume, or negative when it lies
  // inside an odd number of the others (a cavity; CGAL's rule). Its volume
  // from its own centroid; nesting by the winding number of each other
  // component at the centroid of its first face (skipped above 64 components).
  std::vector<soup::Vec3> wv(V.begin(), V.end());
  std::vector<std::vector<Tri>> comp_tris(members.size());
  for (std::size_t c = 0; c < members.size(); ++c)
    for (std::size_t k : members[c]) comp_tris[c].push_back(oriented(k));
  std::vector<soup::WindingNumber> comp_w;
  if (members.size() > 1 && members.size() <= 64)
    for (std::size_t c = 0; c < members.size(); ++c) comp_w.emplace_back(wv, comp_tris[c]);
  for (std::size_t c = 0; c < members.size(); ++c) {
    double cx = 0, cy = 0, cz = 0, n = 0;
    for (const Tri& t : comp_tris[c])
      for (auto v : t) cx += V[v][0], cy += V[v][1], cz += V[v][2], n += 1;
    const Point o(cx / n, cy / n, cz / n);
    double six = 0;
    for (const Tri& t : comp_tris[c]) six += CGAL::determinant(P(t[0]) - o, P(t[1]) - o, P(t[2]) - o);
    std::size_t depth = 0;
    if (!comp_w.empty()) {
      const Tri& f = comp_tris[c][0];
      const soup::Vec3 q{(V[f[0]][0] + V[f[1]][0] + V[f[2]][0]) / 3, (V[f[0]][1] + V[f[1]][1] + V[f[2]][1]) / 3,
                         (V[f[0]][2] + V[f[1]][2] + V[f[2]][2]) / 3};
      for (std::size_t d = 0; d < members.size(); ++d)
        if (d != c && std::abs(comp_w[d].direct(q)) >= 0.5) ++depth;
    }
    const bool want_positive = depth % 2 == 0;
    if (six != 0 && (six > 0) != want_positive) {
      ++r.inward_components;
      for (std::size_t k : members[c]) flip[k] = !flip[k];
    }
  }
  for (std::size_t k = 0; k < kept.size(); ++k) {
    out.tris.push_back(oriented(k));
    out.face.push_back(s.face[kept[k]]);
  }
  // The net boundary: each edge's count one way minus the other.
  std::map<std::pair<std::uint32_t, std::uint32_t>, long> net;
  for (const Tri& t : out.tris)
    for (std::size_t i = 0; i < 3; ++i) {
      const std::uint32_t u = t[i], w = t[(i + 1) % 3];
      net[{std::min(u, w), std::max(u, w)}] += u < w ? 1 : -1;
    }
  for (const auto& [e, m] : net)
    for (long i = 0; i < std::abs(m); ++i) out.boundary.push_back(m > 0 ? e : std::pair{e.second, e.first});

  // Self-intersections among the kept faces: boxes, then exact predicates.
  {
    using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
    std::vector<Box> boxes;
    boxes.reserve(out.tris.size());
    for (std::size_t k = 0; k < out.tris.size(); ++k) {
      const Tri& t = out.tris[k];
      boxes.emplace_back(P(t[0]).bbox() + P(t[1]).bbox() + P(t[2]).bbox(), k);
    }
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
      if (faces_meet(V, out.tris[a.info()], out.tris[b.info()]))
        add(SoupReport::self_intersections, {out.face[a.info()], out.face[b.info()]});
    });
  }

  const auto finish = [](std::vector<std::vector<std::size_t>>& all, SoupFlaw& f) {
    f.count = all.size();
    std::sort(all.begin(), all.end());
    if (all.size() > SoupReport::kListed) all.resize(SoupReport::kListed);
    f.first = std::move(all);
  };
  for (std::size_t k = 0; k < SoupReport::kKinds; ++k) finish(found[k], r.flaws[k]);
  r.bad_normals = bad_normals_of(s);
  return out;
}

/// The solid {w >= 1/2} of a repaired soup (S20, S23).
class SoupShape final : public Shape {
 public:
  SoupShape(const Soup& s, Repaired rep, const std::string& name)
      : name_(basename_of(name)), report_(std::move(rep.report)), wn_(to_soup(s.vertices), rep.tris) {
    const auto P = [&](std::uint32_t v) { return Point(s.vertices[v][0], s.vertices[v][1], s.vertices[v][2]); };
    // Bounds: the vertices of every face of the input.
    bounds_.lo = bounds_.hi = s.vertices[s.triangles.at(0)[0]];
    for (const Tri& t : s.triangles)
      for (auto v : t)
        for (std::size_t k = 0; k < 3; ++k) {
          bounds_.lo[k] = std::min(bounds_.lo[k], s.vertices[v][k]);
          bounds_.hi[k] = std::max(bounds_.hi[k], s.vertices[v][k]);
        }
    // The tree's triangles are (v0, v1, v2), as the clean shape's face-graph
    // primitive gives a face added as (v0, v1, v2); the samples and the
    // volume go through (v2, v0, v1), the clean shape's halfedge order: so
    // that on a clean mesh every number is the clean shape's.
    const Point o(bounds_.lo[0], bounds_.lo[1], bounds_.lo[2]);
    double six_volume = 0;
    for (const Tri& t : rep.tris) {
      tree_triangles_.emplace_back(P(t[0]), P(t[1]), P(t[2]));
      const Point a = P(t[2]), b = P(t[0]), c = P(t[1]);
      triangles_.push_back({a, b, c});
      six_volume += CGAL::determinant(a - o, b - o, c - o);
      area_sum_.push_back((area_sum_.empty() ? 0.0 : area_sum_.back()) +
                          std::sqrt(K::Triangle_3(a, b, c).squared_area()));
    }
    if (tree_triangles_.empty()) throw ShapeError(name + ": encloses no volume (no face is left after the repairs)");
    tree_.insert(tree_triangles_.cbegin(), tree_triangles_.cend());
    tree_.build();
    tree_.accelerate_distance_queries();
    for (const auto& [u, w] : rep.boundary) {
      boundary_.emplace_back(P(u), P(w));
      boundary_length_ += std::sqrt(boundary_.back().squared_length());
    }
    if (!boundary_.empty()) {
      boundary_tree_.insert(boundary_.cbegin(), boundary_.cend());
      boundary_tree_.build();
      boundary_tree_.accelerate_distance_queries();
    }
    // S23: exact for a closed soup without self-intersections, else sampled.
    exact_volume_ = boundary_.empty() && report_.flaws[SoupReport::self_intersections].count == 0;
    volume_ = six_volume / 6;
  }

  /// S20: a closed soup without self-intersections has w = 0 or 1 off its
  /// triangles, each triangle between the two: a point on one (exact, through
  /// the tree) is on the surface, as Side_of_triangle_mesh says of it.
  int side(const Vec3& p) const override {
    if (exact_volume_ && tree_.do_intersect(Point(p[0], p[1], p[2]))) return 0;
    return wn_.side(p);
  }

  /// S20: the distance to the triangles, and across the holes a lower bound
  /// of the distance to where w passes 1/2 (from a bound on |grad w|).
  double distance(const Vec3& p) const override {
    const Point q(p[0], p[1], p[2]);
    const double d = std::sqrt(tree_.squared_distance(q));
    if (boundary_.empty()) return d;
    const auto e = wn_.estimate(p);
    const double delta = std::abs(e.value - 0.5) - e.error;
    if (!(delta > 0)) return 0;
    const double db = std::sqrt(boundary_tree_.squared_distance(q));
    const double x = 4 * 3.14159265358979323846 * delta * db / boundary_length_;
    return std::min(d, db * (x / (1 + x)));
  }

  double signed_distance(const Vec3& p) const override {
    const int s = side(p);
    return s == 0 ? 0 : s * distance(p);
  }

  /// S37: the distance to the triangles, unless an open boundary adds S20's bound.
  bool distance_is_lipschitz() const override { return boundary_.empty(); }
  /// S39: the tree's closest point where the distance is the triangles' alone.
  Nearest nearest(const Vec3& p) const override {
    if (!boundary_.empty()) return {distance(p), std::nullopt};
    const Point q(p[0], p[1], p[2]);
    const Point c = tree_.closest_point(q);
    return {std::sqrt(SoupTree::AABB_traits().squared_distance_object()(q, c)), Vec3{c.x(), c.y(), c.z()}};
  }

  /// S20: the first intersection of [a, b] with the triangles after which the
  /// side differs from a's, else bisection on the side.
  double crossing(const Vec3& a, const Vec3& b) const override {
    if (a == b) return 0;
    const int sa = side(a);
    if (sa == 0) return 0;
    const Point pa(a[0], a[1], a[2]), qb(b[0], b[1], b[2]);
    std::vector<SoupTree::Intersection_and_primitive_id<K::Segment_3>::Type> hits;
    tree_.all_intersections(K::Segment_3(pa, qb), std::back_inserter(hits));
    const K::Vector_3 d = qb - pa;
    const double dd = d.squared_length();
    auto param = [&](const Point& p) { return std::clamp(((p - pa) * d) / dd, 0.0, 1.0); };
    std::vector<std::pair<double, double>> spans;  // [t0, t1] of each hit
    for (const auto& hit : hits) {
      if (const Point* p = boost::get<Point>(&hit.first)) {
        spans.emplace_back(param(*p), param(*p));
      } else if (const K::Segment_3* sg = boost::get<K::Segment_3>(&hit.first)) {
        const double u = param(sg->source()), w = param(sg->target());
        spans.emplace_back(std::min(u, w), std::max(u, w));
      }
    }
    std::sort(spans.begin(), spans.end());
    double end = 0;  // the furthest t1 so far
    for (std::size_t i = 0; i < spans.size(); ++i) {
      end = std::max(end, spans[i].second);
      const double next = i + 1 < spans.size() ? spans[i + 1].first : 1.0;
      if (i + 1 < spans.size() && next <= end) continue;  // overlapping hits: decide after the last
      const double t = (end + next) / 2;
      const int s = i + 1 < spans.size() ? side(at(a, b, t)) : side(b);
      if (s != sa) return spans[i].first;
    }
    // None flips the side: w passes 1/2 away from the triangles.
    return level_crossing(a, b, sa);
  }

  Bounds bounds() const override { return bounds_; }

  double volume() const override {
    if (exact_volume_) return volume_;
    // S23: the fraction of 2^15 uniform points of the box (std::mt19937_64,
    // seed 1) on the inside, times the box's volume.
    std::call_once(sampled_, [this] {
      std::mt19937_64 rng(1);
      std::uniform_real_distribution<double> u(0, 1);
      constexpr int n = 1 << 15;
      double inside = 0;
      for (int i = 0; i < n; ++i) {
        Vec3 p{};
        for (std::size_t k = 0; k < 3; ++k) p[k] = bounds_.lo[k] + u(rng) * (bounds_.hi[k] - bounds_.lo[k]);
        const int s = side(p);
        inside += s < 0 ? 1 : s == 0 ? 0.5 : 0;
      }
      double box = 1;
      for (std::size_t k = 0; k < 3; ++k) box *= bounds_.hi[k] - bounds_.lo[k];
      sampled_volume_ = inside / n * box;
    });
    return sampled_volume_;
  }

  std::vector<Vec3> sample_surface(std::size_t n, std::uint64_t seed) const override {
    return sample_triangles(triangles_, area_sum_, n, seed);
  }

  std::string describe() const override {
    const std::size_t n = report_.flaw_count();
    return "mesh " + name_ + ": " + std::to_string(report_.faces) + " triangles, repaired (" + std::to_string(n) +
           " flaw" + (n == 1 ? "" : "s") + ")";
  }

  const SoupReport* soup_report() const override { return &report_; }
  std::vector<std::array<Vec3, 3>> surface_triangles() const override { return to_vec3(triangles_); }

 private:
  using SoupPrimitive = CGAL::AABB_triangle_primitive<K, std::vector<K::Triangle_3>::const_iterator>;
  using SoupTree = CGAL::AABB_tree<CGAL::AABB_traits<K, SoupPrimitive>>;
  using EdgePrimitive = CGAL::AABB_segment_primitive<K, std::vector<K::Segment_3>::const_iterator>;
  using EdgeTree = CGAL::AABB_tree<CGAL::AABB_traits<K, EdgePrimitive>>;

  static std::vector<soup::Vec3> to_soup(const std::vector<Vec3>& v) { return {v.begin(), v.end()}; }
  /// S20a: the sign of w(p) - 1/2 certified by the first of the estimates
  /// with beta 4, 8 and 16 (from the rung `first` on) whose bound decides
  /// it, with that estimate and its rung; sign 0 (and the beta-16
  /// estimate) when none decides.
  struct LevelSide {
    int sign = 0;
    double value = 0;
    int rung = 0;
  };
  LevelSide level_side(const Vec3& p, int first) const {
    soup::WindingNumber::Estimate e;
    for (int rung = first; rung < 3; ++rung) {
      e = wn_.estimate(p, soup::WindingNumber::kBeta * (1 << rung));
      if (const int sign = soup::WindingNumber::certified_sign(e, 0.5); sign != 0) return {sign, e.value, rung};
    }
    return {0, e.value, 2};
  }

  /// S20a: where w passes 1/2 on [a, b] away from the triangles: regula falsi
  /// (Illinois) on g(t) = s (w - 1/2), s = 1 when a (side sa) is inside,
  /// with a halving every fourth step, on certified signs only: the first
  /// point (the ends included) whose sign no estimate decides is the cut
  /// point; else the bracket is narrowed down to 2^-30 of the segment. Each
  /// step starts at the rung that decided the step before it (the first
  /// step at the higher of the ends').
  double level_crossing(const Vec3& a, const Vec3& b, int sa) const {
    const double s = sa < 0 ? 1 : -1;
    const LevelSide at_a = level_side(a, 0);
    if (at_a.sign == 0) return 0;
    const LevelSide at_b = level_side(b, 0);
    if (at_b.sign == 0) return 1;
    double lo = 0, hi = 1, glo = s * (at_a.value - 0.5), ghi = s * (at_b.value - 0.5);
    int rung = std::max(at_a.rung, at_b.rung);
    int kept = 0;  // 1: lo kept last step, -1: hi kept last step
    for (int step = 0; hi - lo > 0x1p-30; ++step) {
      double t = (lo * ghi - hi * glo) / (ghi - glo);
      if (step % 4 == 3 || !(t > lo && t < hi)) t = (lo + hi) / 2;
      const LevelSide here = level_side(at(a, b, t), rung);
      if (here.sign == 0) return t;
      rung = here.rung;
      const double g = s * (here.value - 0.5);
      if (s * here.sign > 0) {
        lo = t, glo = g;
        if (kept == -1) ghi /= 2;
        kept = -1;
      } else {
        hi = t, ghi = g;
        if (kept == 1) glo /= 2;
        kept = 1;
      }
    }
    return (lo + hi) / 2;
  }

  static Vec3 at(const Vec3& a, const Vec3& b, double t) {
    return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
  }

  std::string name_;
  SoupReport report_;
  soup::WindingNumber wn_;
  std::vector<K::Triangle_3> tree_triangles_;
  SoupTree tree_;
  std::vector<K::Segment_3> boundary_;
  EdgeTree boundary_tree_;
  double boundary_length_ = 0;
  Bounds bounds_;
  bool exact_volume_ = true;
  double volume_ = 0;
  mutable std::once_flag sampled_;
  mutable double sampled_volume_ = 0;
  std::vector<std::array<Point, 3>> triangles_;
  std::vector<double> area_sum_;
};

/// S24: the normalisation of the box of the vertices the faces use (the
/// box both shapes report), after Checker::basics.
Normalisation normalisation_of_soup(const Soup& s, const std::string& name) {
  Bounds box{s.vertices[s.triangles.at(0)[0]], s.vertices[s.triangles.at(0)[0]]};
  for (const Tri& t : s.triangles)
    for (auto v : t)
      for (std::size_t k = 0; k < 3; ++k) {
        box.lo[k] = std::min(box.lo[k], s.vertices[v][k]);
        box.hi[k] = std::max(box.hi[k], s.vertices[v][k]);
      }
  try {
    return normalisation_of(box);
  } catch (const ShapeError& e) {
    throw ShapeError(name + ": " + e.what());
  }
}

/// The soup in S24's local coordinates; a local coordinate below 2^-200 in
/// magnitude (of a box of extent [1, 2)) is flushed to 0, so that no
/// product of up to four coordinates underflows in CGAL's constructions.
Soup normalised_soup(Soup s, const Normalisation& n) {
  for (Vec3& v : s.vertices) {
    v = n.to_local(v);
    for (double& x : v)
      if (std::abs(x) < 0x1p-200) x = 0;
  }
  return s;
}

/// S22's weld: every triangle's corners renamed to the first vertex with
/// the same coordinates (exactly equal doubles, as STL's corners are
/// merged), and how many used vertices were merged so into an earlier one.
std::pair<Soup, std::size_t> welded_soup(Soup s) {
  std::map<Vec3, std::uint32_t> first;
  std::vector<std::uint32_t> to(s.vertices.size());
  for (std::size_t i = 0; i < s.vertices.size(); ++i)
    to[i] = first.try_emplace(s.vertices[i], static_cast<std::uint32_t>(i)).first->second;
  std::vector<char> merged(s.vertices.size(), 0);
  for (auto& t : s.triangles)
    for (auto& v : t) {
      if (to[v] != v) merged[v] = 1;
      v = to[v];
    }
  return {std::move(s), static_cast<std::size_t>(std::count(merged.begin(), merged.end(), 1))};
}

/// Today's shape of a soup in S24's local coordinates that passes today's
/// checks, with the notes of a clean file (`welded`: S22's count); null
/// when a check or the shape refuses it.
std::unique_ptr<Shape> clean_shape_of(const Soup& s, const std::string& name, std::size_t welded) {
  try {
    Checker(s, name).run();
    auto shape = std::make_unique<MeshShape>(s, name);
    Repaired none;
    none.report.file = name;
    none.report.faces = s.triangles.size();
    none.report.bad_normals = bad_normals_of(s);
    none.report.welded_vertices = welded;
    shape->set_report(std::move(none.report), s);
    return shape;
  } catch (const ShapeError&) {
    return nullptr;
  }
}

/// The default path (S21): the refusals of both modes, then today's shape
/// when today's checks pass; else, with repeated vertices welded (S22),
/// today's shape when they pass then, else the soup's (S20-S23).
std::unique_ptr<Shape> soup_shape_of(const Soup& world, const std::string& name, bool force_soup) {
  Checker(world, name).basics();
  const Normalisation n = normalisation_of_soup(world, name);
  if (!force_soup)
    if (auto shape = clean_shape_of(normalised_soup(world, n), name, 0)) return placed(std::move(shape), n);
  auto [welded, count] = welded_soup(world);
  const Soup local = normalised_soup(std::move(welded), n);
  if (!force_soup && count > 0)
    if (auto shape = clean_shape_of(local, name, count)) return placed(std::move(shape), n);
  Repaired repaired = inspect(local, name);
  repaired.report.welded_vertices = count;
  return placed(std::make_unique<SoupShape>(local, std::move(repaired), name), n);
}

std::unique_ptr<Shape> shape_of(const Soup& world, const std::string& name) {
  Checker(world, name).basics();
  const Normalisation n = normalisation_of_soup(world, name);
  const Soup s = normalised_soup(world, n);
  Checker(s, name).run();
  return placed(std::make_unique<MeshShape>(s, name), n);
}

}  // namespace

namespace {

/// How messages name the input: its path, or "stdin" for "-".
std::string input_name(const std::string& path) { return path == "-" ? "stdin" : path; }

/// The soup of the file `path` ("-": standard input) in `format`, or by its
/// extension, or for standard input by its content (io::read_surface).
Soup read_file(const std::string& path, std::optional<io::SurfaceFormat> format) {
  const std::string name = input_name(path);
  std::error_code ec;
  if (path != "-" && std::filesystem::is_directory(path, ec))
    throw ShapeError(path + ": is a directory, expected a file");
  if (path != "-" && !format) {
    format = io::format_of_extension(path);
    if (!format) {
      const auto dot = path.find_last_of('.');
      const auto slash = path.find_last_of('/');
      const std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash)
                                  ? std::string()
                                  : lower(path.substr(dot + 1));
      throw ShapeError(path + ": unknown extension '" + (ext.empty() ? std::string() : "." + ext) +
                       "' (expected .off, .obj, .ply or .stl)");
    }
  }
  std::ostringstream buf;
  if (path == "-") {
    buf << std::cin.rdbuf();
    if (std::cin.bad()) throw ShapeError(name + ": cannot read");
  } else {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ShapeError(path + ": cannot open: " + std::strerror(errno));
    buf << in.rdbuf();
    if (in.bad()) throw ShapeError(path + ": cannot read");
  }
  const std::string data = std::move(buf).str();
  try {
    return io::read_surface(name, data, format);
  } catch (const io::ReadError& e) {
    throw ShapeError(e.what());
  }
}

Soup soup_in_memory(const std::vector<Vec3>& vertices, const std::vector<Tri>& triangles) {
  Soup s;
  s.vertices = vertices;
  s.triangles = triangles;
  s.face.resize(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) s.face[i] = i;
  s.line.assign(triangles.size(), 0);
  return s;
}

}  // namespace

std::unique_ptr<Shape> load_surface(const std::string& path, std::optional<io::SurfaceFormat> format) {
  return shape_of(read_file(path, format), input_name(path));
}

std::unique_ptr<Shape> load_soup(const std::string& path, std::optional<io::SurfaceFormat> format) {
  return soup_shape_of(read_file(path, format), input_name(path), false);
}

std::unique_ptr<Shape> make_mesh_shape(const std::vector<Vec3>& vertices, const std::vector<Tri>& triangles,
                                       const std::string& name) {
  return shape_of(soup_in_memory(vertices, triangles), name);
}

std::unique_ptr<Shape> make_soup_shape(const std::vector<Vec3>& vertices, const std::vector<Tri>& triangles,
                                       const std::string& name, SoupPath path) {
  return soup_shape_of(soup_in_memory(vertices, triangles), name, path == SoupPath::always);
}

SoupReport inspect_soup(const std::vector<Vec3>& vertices, const std::vector<Tri>& triangles, const std::string& name) {
  const Soup s = soup_in_memory(vertices, triangles);
  Checker(s, name).basics();
  return inspect(s, name).report;
}

double max_distance_to_triangles(const std::vector<Vec3>& points, const std::vector<Vec3>& vertices,
                                 const std::vector<Tri>& triangles) {
  if (points.empty()) return 0;
  if (triangles.empty()) throw ShapeError("max_distance_to_triangles: no triangles");
  std::vector<K::Triangle_3> soup;
  soup.reserve(triangles.size());
  auto pt = [&](std::uint32_t v) {
    if (v >= vertices.size())
      throw ShapeError("max_distance_to_triangles: vertex index " + std::to_string(v) + " out of range (" +
                       std::to_string(vertices.size()) + " vertices)");
    return Point(vertices[v][0], vertices[v][1], vertices[v][2]);
  };
  for (const auto& t : triangles) soup.emplace_back(pt(t[0]), pt(t[1]), pt(t[2]));
  using SoupPrimitive = CGAL::AABB_triangle_primitive<K, std::vector<K::Triangle_3>::const_iterator>;
  CGAL::AABB_tree<CGAL::AABB_traits<K, SoupPrimitive>> tree(soup.cbegin(), soup.cend());
  tree.build();
  tree.accelerate_distance_queries();
  // The tree is built once, then queried by two threads, each over half of
  // the points; the maximum is the same whatever the split.
  const auto worst_of = [&](std::size_t begin, std::size_t end) {
    double worst = 0;
    for (std::size_t i = begin; i < end; ++i)
      worst = std::max(worst, std::sqrt(tree.squared_distance(Point(points[i][0], points[i][1], points[i][2]))));
    return worst;
  };
  const std::size_t half = points.size() / 2;
  double second = 0;
  std::thread other([&] { second = worst_of(half, points.size()); });
  const double first = worst_of(0, half);
  other.join();
  return std::max(first, second);
}

}  // namespace bccmis::stuff
