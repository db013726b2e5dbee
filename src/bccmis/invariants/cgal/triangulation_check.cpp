// The checker's CGAL layer (this folder: layer 5 in 2D, layer 6 in d3/).
// The only translation unit that includes CGAL (compile cost ~10-15 s).
#include "bccmis/invariants/cgal/triangulation_check.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

namespace bccmis {

namespace {

using K = CGAL::Epeck;
using TDS = CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<K>,
                                                 CGAL::Constrained_triangulation_face_base_2<K>>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, TDS, CGAL::Exact_intersections_tag>;
// The plus wrapper keeps constraints that CGAL splits at intersections, and is
// silent in Debug builds where the bare CDT warns on crossing constraints.
using Triangulation = CGAL::Constrained_triangulation_plus_2<CDT>;
using VertexHandle = Triangulation::Vertex_handle;

__extension__ using Int128 = __int128;

std::string pos(const Point& p) { return to_string(p); }

// An int64 as an exact number (doubles are exact up to 2^53).
K::FT exact(std::int64_t v) {
  if (v > -(std::int64_t{1} << 53) && v < (std::int64_t{1} << 53)) return K::FT(static_cast<double>(v));
  const std::int64_t hi = v >> 32;  // arithmetic shift: v = hi * 2^32 + lo
  const auto lo = static_cast<std::uint32_t>(v & 0xffffffff);
  return K::FT(static_cast<double>(hi)) * K::FT(4294967296.0) + K::FT(static_cast<double>(lo));
}

K::Point_2 point(const Point& p) { return {exact(p.x), exact(p.y)}; }

// Sorts the boundary nodes of a cell counter-clockwise around its center,
// starting at angle 0 (exact: 128-bit cross products of 64-bit differences).
std::vector<Point> angular(const Point& c, const PointSet& ring) {
  std::vector<Point> out(ring.begin(), ring.end());
  auto upper = [&c](const Point& p) {
    const Int128 dx = Int128{p.x} - c.x, dy = Int128{p.y} - c.y;
    return dy > 0 || (dy == 0 && dx > 0);
  };
  std::sort(out.begin(), out.end(), [&](const Point& a, const Point& b) {
    const bool ua = upper(a), ub = upper(b);
    if (ua != ub) return ua;
    const Int128 ax = Int128{a.x} - c.x, ay = Int128{a.y} - c.y, bx = Int128{b.x} - c.x, by = Int128{b.y} - c.y;
    // All coordinates lie in [0, 2^62] (checked first), so differences are
    // below 2^62 and every product and sum fits in 128 bits.
    const Int128 cross = ax * by - ay * bx;
    if (cross != 0) return cross > 0;
    return ax * ax + ay * ay < bx * bx + by * by;  // collinear: nearer first
  });
  return out;
}

using Edge = std::pair<Point, Point>;  // ordered: first < second
Edge edge(const Point& a, const Point& b) { return a < b ? Edge{a, b} : Edge{b, a}; }

std::string approx(const K::Point_2& p) {
  std::ostringstream s;
  s << "(" << CGAL::to_double(p.x()) << ", " << CGAL::to_double(p.y()) << ")";
  return s.str();
}

Violation violation(std::string code, std::vector<Point> where, const std::string& text, std::string section) {
  Violation v;
  v.message = code + ": " + text;
  v.code = std::move(code);
  v.where = std::move(where);
  v.section = std::move(section);
  v.layer = 5;
  return v;
}

}  // namespace

std::optional<Violation> find_triangulation_violation(const Graph& g) {
  const std::int64_t S = std::int64_t{1} << (g.size.L + 1);
  const std::int64_t width = g.size.W * S, height = g.size.H * S;
  // Every vertex lies in the domain (this also keeps the 128-bit angular
  // comparisons below exact: coordinates are then at most 2^62).
  for (const PointSet* set : {&g.C, &g.N})
    for (const Point& v : *set)
      if (v.x < 0 || v.y < 0 || v.x > width || v.y > height)
        return violation("hull-domain", {v},
                         "the vertex " + pos(v) + " lies outside the domain [0, " + std::to_string(width) + "] x [0, " +
                             std::to_string(height) + "]",
                         "§1 ¶6");

  // The expected edges: graph edges and the hull edges of eq. (1), each with
  // a note saying where it comes from.
  std::map<Edge, std::string> expected;
  auto is_vertex = [&g](const Point& v) { return g.N.count(v) != 0 || g.C.count(v) != 0; };
  for (const Point& c : g.C) {
    PointSet ring;
    for (const Point& n : g.nbr(c))
      if (is_vertex(n)) {
        ring.insert(n);
        expected.emplace(edge(c, n), "graph edge of center " + pos(c));
      }
    if (ring.size() < 2) continue;
    const std::vector<Point> hull = angular(c, ring);
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const Point& a = hull[i];
      const Point& b = hull[(i + 1) % hull.size()];
      if (a != b) expected.emplace(edge(a, b), "hull edge of center " + pos(c) + ", eq. (1)");
    }
  }

  Triangulation t;
  std::map<Point, VertexHandle> handle;
  std::map<VertexHandle, Point> vertex;
  for (const PointSet* set : {&g.N, &g.C})
    for (const Point& v : *set) {
      const VertexHandle h = t.insert(point(v));
      handle[v] = h;
      vertex[h] = v;
    }
  for (const auto& [e, why] : expected) t.insert_constraint(handle.at(e.first), handle.at(e.second));

  // constraint-crossing: CGAL added a vertex where two constraints cross.
  for (auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v) {
    if (vertex.count(v)) continue;
    const K::Point_2 x = v->point();
    std::vector<Point> where;
    std::string names;
    for (const auto& [e, why] : expected) {
      const K::Segment_2 s(point(e.first), point(e.second));
      if (s.has_on(x)) {
        where.push_back(e.first);
        where.push_back(e.second);
        names += std::string(names.empty() ? "" : " and ") + pos(e.first) + "-" + pos(e.second) + " (" + why + ")";
      }
    }
    return violation("constraint-crossing", where, "the edges " + names + " cross at " + approx(x), "§2 eq. (1)");
  }

  // missing-edge: every graph and hull edge is an edge of the triangulation.
  for (const auto& [e, why] : expected) {
    if (t.is_edge(handle.at(e.first), handle.at(e.second))) continue;
    std::string on;
    std::vector<Point> where{e.first, e.second};
    const K::Segment_2 s(point(e.first), point(e.second));
    for (const auto& [p, h] : handle)
      if (p != e.first && p != e.second && s.has_on(h->point())) {
        on = "; vertex " + pos(p) + " lies on it";
        where.push_back(p);
        break;
      }
    return violation("missing-edge", where,
                     "the edge " + pos(e.first) + "-" + pos(e.second) + " (" + why +
                         ") is not an edge of CGAL's constrained triangulation" + on,
                     "§2 eq. (1)");
  }

  // extra-edge: nothing else is an edge of the triangulation.
  std::set<Edge> actual;
  for (auto e = t.finite_edges_begin(); e != t.finite_edges_end(); ++e) {
    const VertexHandle a = e->first->vertex(Triangulation::cw(e->second));
    const VertexHandle b = e->first->vertex(Triangulation::ccw(e->second));
    actual.insert(edge(vertex.at(a), vertex.at(b)));
  }
  for (const Edge& e : actual)
    if (!expected.count(e))
      return violation("extra-edge", {e.first, e.second},
                       "CGAL's triangulation has the edge " + pos(e.first) + "-" + pos(e.second) +
                           ", which is neither a graph edge nor a hull edge of eq. (1)",
                       "§2 eq. (1)");

  // hull-domain: the triangulated region, the convex hull of the vertices,
  // is the domain [0, W*S] x [0, H*S]: its corners are vertices and every
  // hull vertex lies on the domain boundary.
  {
    for (const Point corner : {Point{0, 0}, Point{0, height}, Point{width, 0}, Point{width, height}})
      if (!handle.count(corner))
        return violation("hull-domain", {corner},
                         "the domain corner " + pos(corner) +
                             " is not a vertex, so the triangulation does not cover the domain",
                         "§1 ¶6");
    if (t.dimension() == 2) {
      auto circ = t.incident_vertices(t.infinite_vertex()), done = circ;
      do {
        const Point p = vertex.at(circ);
        if (p.x != 0 && p.y != 0 && p.x != width && p.y != height)
          return violation("hull-domain", {p},
                           "the vertex " + pos(p) +
                               " is on the convex hull of the vertices but not on the domain boundary",
                           "§1 ¶6");
      } while (++circ != done);
    }
  }

  // triangle-count: one star triangle per boundary edge of each cell, and
  // Euler's formula for a triangulated disk, F = 2V - h - 2.
  std::size_t star = 0;
  for (const Point& c : g.C) star += g.nbr(c).size();
  const std::size_t faces = t.number_of_faces();
  std::size_t hull = 0;
  if (t.dimension() == 2) {
    auto circ = t.incident_vertices(t.infinite_vertex()), done = circ;
    do ++hull;
    while (++circ != done);
  }
  const std::size_t V = t.number_of_vertices();
  const long long euler = 2LL * static_cast<long long>(V) - static_cast<long long>(hull) - 2;
  if (faces != star || static_cast<long long>(faces) != euler)
    return violation("triangle-count", {},
                     "CGAL's triangulation has " + std::to_string(faces) + " triangles; the cells' stars give " +
                         std::to_string(star) + " and Euler's formula 2V - h - 2 gives " + std::to_string(euler) +
                         " (V = " + std::to_string(V) + ", h = " + std::to_string(hull) + ")",
                     "§1 ¶6");

  // not-delaunay: every edge between two triangles is locally Delaunay.
  for (auto e = t.finite_edges_begin(); e != t.finite_edges_end(); ++e) {
    const auto f = e->first;
    const int i = e->second;
    const auto nf = f->neighbor(i);
    if (t.is_infinite(f) || t.is_infinite(nf)) continue;
    const VertexHandle opposite = t.mirror_vertex(f, i);
    const VertexHandle a = f->vertex(0), b = f->vertex(1), c = f->vertex(2);  // counter-clockwise
    if (CGAL::side_of_oriented_circle(a->point(), b->point(), c->point(), opposite->point()) ==
        CGAL::ON_POSITIVE_SIDE) {
      const Point pa = vertex.at(a), pb = vertex.at(b), pc = vertex.at(c), pd = vertex.at(opposite);
      return violation("not-delaunay", {pa, pb, pc, pd},
                       "the edge " + pos(vertex.at(f->vertex(Triangulation::cw(i)))) + "-" +
                           pos(vertex.at(f->vertex(Triangulation::ccw(i)))) + " is not locally Delaunay: " + pos(pd) +
                           " lies strictly inside the circle through " + pos(pa) + ", " + pos(pb) + " and " + pos(pc),
                       "§1 ¶6");
    }
  }
  return std::nullopt;
}

}  // namespace bccmis
