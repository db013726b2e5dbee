#include "bccmis/oracle/oracle.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <set>
#include <span>
#include <string_view>
#include <utility>

#include "bccmis/d3/mesh.h"
#include "bccmis/geometry.h"
#include "bccmis/io/svg.h"
#include "bccmis/json_writer.h"

namespace bccmis {

namespace {

template <class P>
std::string pos(const P& p) {
  return to_string(p);
}

template <class Set>
std::string list(const Set& s) {
  std::string r;
  for (const auto& p : s) {
    if (!r.empty()) r += ' ';
    r += pos(p);
  }
  return r.empty() ? "none" : r;
}

std::string lattice_text(const LatticeSize& s) {
  return std::to_string(s.W) + " " + std::to_string(s.H) + " " + std::to_string(s.L);
}
std::string lattice_text(const d3::LatticeSize& s) {
  return std::to_string(s.W) + " " + std::to_string(s.H) + " " + std::to_string(s.D) + " " + std::to_string(s.L);
}

// Which kind a position has in g, for messages.
template <class G>
std::string kind(const G& g, const typename G::point_type& p) {
  if (g.is_center(p)) {
    auto it = g.level.find(p);
    return "center " + pos(p) + (it == g.level.end() ? "" : " level " + std::to_string(it->second));
  }
  return "node " + pos(p);
}

}  // namespace

namespace {

// diff_states for either dimension.
template <class G>
std::vector<std::string> diff_states_as(const G& a, const G& b) {
  using P = typename G::point_type;
  using Set = std::set<P>;
  std::vector<std::string> out;
  if (!(a.size == b.size)) out.push_back("lattice: A is " + lattice_text(a.size) + ", B is " + lattice_text(b.size));
  Set all;
  for (const G* g : {&a, &b}) {
    all.insert(g->N.begin(), g->N.end());
    all.insert(g->C.begin(), g->C.end());
  }
  for (const P& p : all) {
    const bool in_a = a.is_center(p) || a.is_node(p);
    const bool in_b = b.is_center(p) || b.is_node(p);
    if (!in_b) {
      out.push_back("only in A: " + kind(a, p));
      continue;
    }
    if (!in_a) {
      out.push_back("only in B: " + kind(b, p));
      continue;
    }
    if (a.is_center(p) != b.is_center(p)) {
      out.push_back(pos(p) + ": " + (a.is_center(p) ? "a center" : "a node") + " in A, " +
                    (b.is_center(p) ? "a center" : "a node") + " in B");
      continue;
    }
    if (a.is_center(p) && a.level.count(p) && b.level.count(p) && a.level.at(p) != b.level.at(p))
      out.push_back(pos(p) + ": level " + std::to_string(a.level.at(p)) + " in A, " + std::to_string(b.level.at(p)) +
                    " in B");
    const Set& na = a.nbr(p);
    const Set& nb = b.nbr(p);
    if (na != nb) {
      Set only_a, only_b;
      std::set_difference(na.begin(), na.end(), nb.begin(), nb.end(), std::inserter(only_a, only_a.end()));
      std::set_difference(nb.begin(), nb.end(), na.begin(), na.end(), std::inserter(only_b, only_b.end()));
      out.push_back("neighbors of " + pos(p) + ": only in A: " + list(only_a) + "; only in B: " + list(only_b));
    }
  }
  return out;
}

// The reference graph's memory, estimated: libstdc++ red-black tree nodes
// are 32 bytes of header plus the value, rounded to 8 (a point is 16 bytes
// in 2D, 24 in 3D); a std::set header is 48 bytes. `entries`: the total size
// of the neighbor sets.
template <class G>
std::size_t reference_bytes(const G& g, std::size_t entries) {
  constexpr std::size_t point = sizeof(typename decltype(g.C)::value_type);
  const std::size_t set_node = 32 + point, nbr_map_node = 32 + point + 48, level_node = 32 + point + 8;
  return set_node * (g.N.size() + g.C.size()) + nbr_map_node * g.neighbors.size() + set_node * entries +
         level_node * g.level.size();
}

// `bccmis stats` in both dimensions: a head (JSON members already begun in
// `head`, or text lines), the cells, the cells per level, then named counts;
// text lines "name value", or one line of JSON.
using Count = std::pair<const char*, std::size_t>;
std::string format_counts(bool json, JsonWriter head, const std::string& head_text, std::size_t cells,
                          const std::map<int, std::size_t>& cells_per_level, std::span<const Count> counts) {
  if (json) {
    head.member("cells", cells).key("cells_per_level").begin_object();
    for (const auto& [l, n] : cells_per_level) head.member(std::to_string(l), n);
    head.end_object();
    for (const auto& [name, n] : counts) head.member(name, n);
    return head.end_object().str() + "\n";
  }
  std::string out = head_text + "cells " + std::to_string(cells) + "\n";
  for (const auto& [l, n] : cells_per_level) out += "cells_level_" + std::to_string(l) + " " + std::to_string(n) + "\n";
  for (const auto& [name, n] : counts) out += std::string(name) + " " + std::to_string(n) + "\n";
  return out;
}

}  // namespace

std::vector<std::string> diff_states(const Graph& a, const Graph& b) { return diff_states_as(a, b); }
std::vector<std::string> diff_states(const d3::Graph& a, const d3::Graph& b) { return diff_states_as(a, b); }

Stats stats(const Graph& g) {
  Stats s;
  s.cells = g.C.size();
  s.nodes = g.N.size();
  for (const auto& [c, l] : g.level) ++s.cells_per_level[l];
  for (const Point& n : g.N)
    if (g.nbr(n).size() == 3) ++s.junctions;
  std::set<std::pair<Point, Point>> hull;
  std::size_t entries = 0;
  for (const auto& [v, nbrs] : g.neighbors) entries += nbrs.size();
  for (const Point& c : g.C) {
    s.graph_edges += g.nbr(c).size();
    s.triangles += g.nbr(c).size();
    const std::vector<Point> ring = boundary_in_angular_order(g, c);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      Point p = ring[i], q = ring[(i + 1) % ring.size()];
      if (q < p) std::swap(p, q);
      hull.insert({p, q});
    }
  }
  s.hull_edges = hull.size();
  s.reference_bytes = reference_bytes(g, entries);
  return s;
}

std::string format_stats(const Stats& s, bool json) {
  const Count counts[] = {
      {"nodes", s.nodes},           {"junctions", s.junctions}, {"graph_edges", s.graph_edges},
      {"hull_edges", s.hull_edges}, {"triangles", s.triangles}, {"reference_bytes_estimate", s.reference_bytes}};
  JsonWriter head;
  head.begin_object();
  return format_counts(json, std::move(head), "", s.cells, s.cells_per_level, counts);
}

std::set<std::pair<d3::Point, d3::Point>> green_edges(const d3::Graph& g) {
  std::set<std::pair<d3::Point, d3::Point>> green;
  for (const d3::Point& c : g.C) {
    const std::int64_t h = d3::cell_side(g.size, g.level_of(c)) / 2;
    // The 12 cube edges: along axis a, the other two coordinates at c +- h.
    for (int a = 0; a < 3; ++a)
      for (const std::int64_t du : {-h, h})
        for (const std::int64_t dv : {-h, h}) {
          std::vector<d3::Point> on_edge;
          for (const d3::Point& n : g.nbr(c)) {
            const std::array<std::int64_t, 3> d{n.x - c.x, n.y - c.y, n.z - c.z};
            if (d[(a + 1) % 3] == du && d[(a + 2) % 3] == dv) on_edge.push_back(n);
          }
          // Sorted by (x, y, z), so along the edge; consecutive nodes bound a segment.
          for (std::size_t i = 1; i < on_edge.size(); ++i) green.insert({on_edge[i - 1], on_edge[i]});
        }
  }
  return green;
}

d3::Stats stats(const d3::Graph& g) {
  d3::Stats s;
  s.size = g.size;
  s.cells = g.C.size();
  s.nodes = g.N.size();
  for (const auto& [c, l] : g.level) ++s.cells_per_level[l];
  for (const d3::Point& n : g.N) {
    const std::size_t k = g.nbr(n).size();
    if ((k & (k - 1)) != 0) ++s.junctions;  // not a power of two: 3, 5, 6 or 7 (F1, F2)
  }
  std::size_t entries = 0;
  for (const auto& [v, nbrs] : g.neighbors) entries += nbrs.size();
  for (const d3::Point& c : g.C) s.graph_edges += g.nbr(c).size();
  s.green_edges = green_edges(g).size();
  const std::vector<d3::Tet> tets = d3::tetrahedra(g);
  s.tetrahedra = tets.size();
  std::set<d3::Point> hull;
  for (const d3::Tet& t : tets)
    for (const d3::Point& v : t)
      if (!g.is_node(v) && !g.is_center(v)) hull.insert(v);
  s.hull_vertices = hull.size();
  s.reference_bytes = reference_bytes(g, entries);
  return s;
}

std::string format_stats(const d3::Stats& s, bool json) {
  const Count counts[] = {{"nodes", s.nodes},
                          {"junctions", s.junctions},
                          {"graph_edges", s.graph_edges},
                          {"green_edges", s.green_edges},
                          {"tetrahedra", s.tetrahedra},
                          {"hull_vertices", s.hull_vertices},
                          {"reference_bytes_estimate", s.reference_bytes}};
  JsonWriter head;
  head.begin_object().member("dimension", 3).key("lattice").begin_array();
  for (const std::int64_t n : {s.size.W, s.size.H, s.size.D, static_cast<std::int64_t>(s.size.L)}) head.value(n);
  head.end_array();
  return format_counts(json, std::move(head), "lattice " + lattice_text(s.size) + "\n", s.cells, s.cells_per_level,
                       counts);
}

std::string render_svg(const Graph& g, const std::string& title, std::string_view overlay) {
  const double S = static_cast<double>(level0_side(g.size));
  const double w = static_cast<double>(g.size.W) * S, h = static_cast<double>(g.size.H) * S;
  const double scale = 760.0 / std::max(w, h), margin = 20.0;
  const double width = w * scale + 2 * margin, height = h * scale + 2 * margin + 40;
  char buf[256];
  auto X = [&](std::int64_t x) { return margin + static_cast<double>(x) * scale; };
  auto Y = [&](std::int64_t y) { return margin + (h - static_cast<double>(y)) * scale; };
  std::string out = io::svg_header(width, height, title);
  // Cells shaded by level.
  static const char* shades[] = {"#f2f2f2", "#dde8f5", "#c2d6ee", "#a3c1e5", "#84abdb", "#6796d0", "#4c81c4"};
  out += "<g stroke=\"none\">\n";
  for (const Point& c : g.C) {
    auto it = g.level.find(c);
    const int l = it == g.level.end() ? 0 : it->second;
    const double half = static_cast<double>(cell_side(g.size, std::clamp(l, 0, g.size.L))) / 2 * scale;
    std::snprintf(buf, sizeof buf, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"%s\"/>\n",
                  X(c.x) - half, Y(c.y) - half, 2 * half, 2 * half, shades[std::clamp(l, 0, 6)]);
    out += buf;
  }
  out += "</g>\n";
  // Hull edges of eq. (1), dashed.
  std::set<std::pair<Point, Point>> hull;
  for (const Point& c : g.C) {
    const std::vector<Point> ring = boundary_in_angular_order(g, c);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      Point p = ring[i], q = ring[(i + 1) % ring.size()];
      if (q < p) std::swap(p, q);
      hull.insert({p, q});
    }
  }
  out += "<g stroke=\"#2060b0\" stroke-width=\"1.2\" stroke-dasharray=\"4 3\">\n";
  for (const auto& [p, q] : hull) {
    std::snprintf(buf, sizeof buf, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", X(p.x), Y(p.y), X(q.x),
                  Y(q.y));
    out += buf;
  }
  out += "</g>\n";
  // Graph edges (node-center), solid.
  out += "<g stroke=\"#333333\" stroke-width=\"0.8\">\n";
  for (const Point& c : g.C)
    for (const Point& n : g.nbr(c)) {
      std::snprintf(buf, sizeof buf, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", X(c.x), Y(c.y),
                    X(n.x), Y(n.y));
      out += buf;
    }
  out += "</g>\n";
  // Nodes, junctions, centers; markers shrink with the finest cell on screen.
  int finest = 0;
  for (const auto& [c, l] : g.level) finest = std::max(finest, std::clamp(l, 0, g.size.L));
  const double cell_px = static_cast<double>(cell_side(g.size, finest)) * scale;
  const double r_node = std::clamp(cell_px / 10, 0.5, 2.5), r_ring = std::clamp(cell_px / 5, 1.0, 5.0);
  const double center_px = std::clamp(cell_px / 8, 0.8, 4.0);
  out += "<g>\n";
  for (const Point& n : g.N) {
    const bool junction = g.nbr(n).size() == 3;
    out += io::circle(X(n.x), Y(n.y), r_node, "fill=\"#2a7a2a\"");
    if (junction) {
      std::snprintf(buf, sizeof buf, "fill=\"none\" stroke=\"#d02020\" stroke-width=\"%.2f\"", r_ring / 3);
      out += io::circle(X(n.x), Y(n.y), r_ring, buf);
    }
  }
  for (const Point& c : g.C) {
    std::snprintf(buf, sizeof buf, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"#c03030\"/>\n",
                  X(c.x) - center_px / 2, Y(c.y) - center_px / 2, center_px, center_px);
    out += buf;
  }
  out += "</g>\n";
  const std::string_view font = "font-family=\"sans-serif\" font-size=\"12\"";
  out += io::text_start(margin, height - 22, font) + io::xml_escape(title) + ": " + std::to_string(g.C.size()) +
         " cells, " + std::to_string(g.N.size()) + " nodes.</text>\n";
  out += io::text_start(margin, height - 6, font) +
         "Solid: stored edges; dashed: hull edges of eq. (1); red rings: junctions.</text>\n";
  out += overlay;
  out += io::svg_end();
  return out;
}

}  // namespace bccmis
