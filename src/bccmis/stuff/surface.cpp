// Closed triangle meshes as shapes (spec/stuffing.md §1): the OFF, OBJ and
// STL files read (by bccmis/io/), the checks that make a triangle soup a
// closed, manifold, consistently oriented, self-intersection free surface,
// and the Shape over it. The only translation unit of bccmis::stuff that
// includes CGAL.
#include "bccmis/stuff/surface.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <string_view>
#include <utility>

#include "bccmis/io/obj.h"
#include "bccmis/io/off.h"
#include "bccmis/io/read_error.h"
#include "bccmis/io/stl.h"
#include "bccmis/io/triangle_soup.h"

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

  void run() const {
    const auto& V = s_.vertices;
    const auto& T = s_.triangles;
    if (T.empty()) fail("empty mesh (no faces)");
    for (std::size_t i = 0; i < V.size(); ++i)
      for (double x : V[i])
        if (!std::isfinite(x)) fail("vertex " + vertex(static_cast<std::uint32_t>(i)) + " has a coordinate not finite");
    for (std::size_t t = 0; t < T.size(); ++t) {
      for (auto v : T[t])
        if (v >= V.size())
          fail(face(t) + ": vertex index " + vertex(v) + " out of range (" + std::to_string(V.size()) + " vertices)");
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

class MeshShape final : public Shape {
 public:
  MeshShape(const Soup& s, const std::string& name) : name_(basename_of(name)) {
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
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Vec3> out;
    out.reserve(n);
    const double total = area_sum_.back();
    for (std::size_t i = 0; i < n; ++i) {
      const double pick = u(rng) * total;
      const auto it = std::upper_bound(area_sum_.begin(), area_sum_.end(), pick);
      const std::size_t t =
          std::min<std::size_t>(static_cast<std::size_t>(it - area_sum_.begin()), area_sum_.size() - 1);
      // Uniform on the triangle: sqrt of one variable, the other linear.
      const double r = std::sqrt(u(rng)), w = u(rng);
      const auto& [a, b, c] = triangles_[t];
      const double ca = 1 - r, cb = r * (1 - w), cc = r * w;
      out.push_back({ca * a.x() + cb * b.x() + cc * c.x(), ca * a.y() + cb * b.y() + cc * c.y(),
                     ca * a.z() + cb * b.z() + cc * c.z()});
    }
    return out;
  }

  std::string describe() const override {
    return "mesh " + name_ + ": " + std::to_string(triangles_.size()) + " triangles";
  }

 private:
  std::string name_;
  Mesh mesh_;
  Tree tree_;
  std::optional<Side> side_;
  double volume_ = 0;
  Bounds bounds_;
  std::vector<std::array<Point, 3>> triangles_;
  std::vector<double> area_sum_;
};

std::unique_ptr<Shape> shape_of(const Soup& s, const std::string& name) {
  Checker(s, name).run();
  return std::make_unique<MeshShape>(s, name);
}

}  // namespace

std::unique_ptr<Shape> load_surface(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  const std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash)
                              ? std::string()
                              : lower(path.substr(dot + 1));
  if (ext != "off" && ext != "obj" && ext != "stl")
    throw ShapeError(path + ": unknown extension '" + (ext.empty() ? std::string() : "." + ext) +
                     "' (expected .off, .obj or .stl)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ShapeError(path + ": cannot open: " + std::strerror(errno));
  std::ostringstream buf;
  buf << in.rdbuf();
  if (in.bad()) throw ShapeError(path + ": cannot read");
  const std::string data = std::move(buf).str();
  Soup s;
  try {
    s = ext == "off" ? io::read_off(path, data) : ext == "obj" ? io::read_obj(path, data) : io::read_stl(path, data);
  } catch (const io::ReadError& e) {
    throw ShapeError(e.what());
  }
  return shape_of(s, path);
}

std::unique_ptr<Shape> make_mesh_shape(const std::vector<Vec3>& vertices, const std::vector<Tri>& triangles,
                                       const std::string& name) {
  Soup s;
  s.vertices = vertices;
  s.triangles = triangles;
  s.face.resize(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) s.face[i] = i;
  s.line.assign(triangles.size(), 0);
  return shape_of(s, name);
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
  tree.accelerate_distance_queries();
  double worst = 0;
  for (const auto& p : points) worst = std::max(worst, std::sqrt(tree.squared_distance(Point(p[0], p[1], p[2]))));
  return worst;
}

}  // namespace bccmis::stuff
