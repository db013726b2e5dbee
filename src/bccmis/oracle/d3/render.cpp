// The 3D picture of `bccmis render` (oracle.h d3::render_svg): the domain box's
// visible boundary triangles in a cabinet projection beside one axis-aligned
// slice through the lattice.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/d3/mesh.h"
#include "bccmis/io/svg.h"
#include "bccmis/oracle/oracle.h"

namespace bccmis {

namespace {

using Extents = std::array<std::int64_t, 3>;

std::int64_t coord(const d3::Point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

Extents extents(const d3::LatticeSize& s) {
  const std::int64_t S = d3::level0_side(s);
  return {s.W * S, s.H * S, s.D * S};
}

const char* axis_name(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

// Fill colour of a leaf of `level` (light grey at level 0, darker blue for
// finer leaves), scaled by a face's brightness.
std::string shade(int level, double brightness) {
  static const int rgb[7][3] = {{0xee, 0xee, 0xee}, {0xc6, 0xda, 0xf0}, {0x9c, 0xbf, 0xe4}, {0x72, 0xa3, 0xd6},
                                {0x4f, 0x86, 0xc6}, {0x36, 0x6a, 0xad}, {0x25, 0x50, 0x8c}};
  const int l = std::clamp(level, 0, 6);
  auto channel = [&](int i) { return static_cast<int>(std::lround(rgb[l][i] * brightness)); };
  return io::hex_colour(channel(0), channel(1), channel(2));
}

// The three box faces a viewer of the cabinet projection sees, with the
// brightness that gives the picture its depth.
struct VisibleFace {
  int axis;
  bool far;  // the plane is at the box's extent (else at 0)
  double brightness;
};
constexpr std::array<VisibleFace, 3> kVisible{{{1, false, 0.88}, {2, true, 1.0}, {0, true, 0.74}}};

// The box face of `kVisible` holding every point of `pts`, or -1.
template <class Points>
int visible_face(const Points& pts, const Extents& ext) {
  for (int f = 0; f < 3; ++f) {
    const VisibleFace& vf = kVisible[static_cast<std::size_t>(f)];
    const std::int64_t plane = vf.far ? ext[static_cast<std::size_t>(vf.axis)] : 0;
    if (std::all_of(pts.begin(), pts.end(), [&](const d3::Point& p) { return coord(p, vf.axis) == plane; })) return f;
  }
  return -1;
}

// A boundary triangle: its vertices (sorted) and the leaf of its tetrahedron.
struct BoundaryTriangle {
  std::array<d3::Point, 3> v;
  d3::Point leaf;
};

// The triangles of exactly one tetrahedron (spec/mesh3d.md §6).
std::vector<BoundaryTriangle> boundary_triangles(const std::vector<d3::Tet>& tets) {
  std::map<std::array<d3::Point, 3>, std::pair<int, d3::Point>> count;
  for (const d3::Tet& t : tets)
    for (std::size_t skip = 0; skip < 4; ++skip) {
      std::array<d3::Point, 3> f{};
      std::size_t k = 0;
      for (std::size_t i = 0; i < 4; ++i)
        if (i != skip) f[k++] = t[i];
      std::sort(f.begin(), f.end());
      ++count.try_emplace(f, 0, t[0]).first->second.first;
    }
  std::vector<BoundaryTriangle> out;
  for (const auto& [f, n_leaf] : count)
    if (n_leaf.first == 1) out.push_back({f, n_leaf.second});
  return out;
}

}  // namespace

SlicePlane middle_slice(const d3::LatticeSize& size) { return {2, extents(size)[2] / 2}; }

std::vector<d3::Point> sliced_leaves(const d3::Graph& g, const SlicePlane& slice) {
  const std::int64_t top = extents(g.size)[static_cast<std::size_t>(std::clamp(slice.axis, 0, 2))];
  std::vector<d3::Point> out;
  for (const d3::Point& c : g.C) {
    const std::int64_t h = d3::cell_side(g.size, g.level_of(c)) / 2;
    const std::int64_t lo = coord(c, slice.axis) - h, hi = coord(c, slice.axis) + h;
    if ((lo <= slice.value && slice.value < hi) || (slice.value == top && hi == top)) out.push_back(c);
  }
  return out;
}

std::string d3::render_svg(const d3::Graph& g, const std::string& title, const SlicePlane& slice) {
  const Extents ext = extents(g.size);
  if (slice.axis < 0 || slice.axis > 2) throw std::invalid_argument("slice axis must be 0, 1 or 2 (x, y or z)");
  const auto sa = static_cast<std::size_t>(slice.axis);
  if (slice.value < 0 || slice.value > ext[sa])
    throw std::invalid_argument(std::string("slice ") + axis_name(slice.axis) + " = " + std::to_string(slice.value) +
                                " is outside the box: " + axis_name(slice.axis) + " in [0, " + std::to_string(ext[sa]) +
                                "]");
  const double ex = static_cast<double>(ext[0]), ey = static_cast<double>(ext[1]), ez = static_cast<double>(ext[2]);
  // Cabinet projection: y recedes up-right at 45 degrees, at half scale.
  const double k = 0.5 * std::sqrt(0.5);
  const double box_w = ex + k * ey, box_h = ez + k * ey;
  // The slice panel: the two other axes, the smaller one to the right.
  const int ua = slice.axis == 0 ? 1 : 0, va = slice.axis == 2 ? 1 : 2;
  const double sw = static_cast<double>(ext[static_cast<std::size_t>(ua)]);
  const double sh = static_cast<double>(ext[static_cast<std::size_t>(va)]);
  const double scale = std::min(1000.0 / (box_w + sw), 520.0 / std::max(box_h, sh));
  const double margin = 20, gap = 50, head = 30;
  const double width = (box_w + sw) * scale + gap + 2 * margin;
  const double panel_h = std::max(box_h, sh) * scale;
  const double height = margin + head + panel_h + 70;
  const double top = margin + head;
  auto PX = [&](const d3::Point& p) {
    return margin + (static_cast<double>(p.x) + k * static_cast<double>(p.y)) * scale;
  };
  auto PY = [&](const d3::Point& p) {
    return top + (box_h - static_cast<double>(p.z) - k * static_cast<double>(p.y)) * scale;
  };
  const double sx0 = margin + box_w * scale + gap;
  auto SX = [&](std::int64_t u) { return sx0 + static_cast<double>(u) * scale; };
  auto SY = [&](std::int64_t v) { return top + (sh - static_cast<double>(v)) * scale; };

  char buf[320];
  std::string out = io::svg_header(width, height, title);

  // Left panel: the visible boundary triangles, filled by level and shaded per face.
  const std::vector<d3::Tet> tets = d3::tetrahedra(g);
  const std::vector<BoundaryTriangle> boundary = boundary_triangles(tets);
  std::size_t drawn = 0;
  out += "<g stroke=\"#555555\" stroke-width=\"0.6\" stroke-linejoin=\"round\">\n";
  for (const BoundaryTriangle& t : boundary) {
    const int f = visible_face(t.v, ext);
    if (f < 0) continue;
    ++drawn;
    const std::string fill = shade(g.level_of(t.leaf), kVisible[static_cast<std::size_t>(f)].brightness);
    std::snprintf(buf, sizeof buf, "<polygon class=\"tri\" points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\" fill=\"%s\"/>\n",
                  PX(t.v[0]), PY(t.v[0]), PX(t.v[1]), PY(t.v[1]), PX(t.v[2]), PY(t.v[2]), fill.c_str());
    out += buf;
  }
  out += "</g>\n";
  // The green edges on the visible faces.
  out += "<g stroke=\"#1f7a1f\" stroke-width=\"2.2\" stroke-linecap=\"round\">\n";
  for (const auto& [a, b] : green_edges(g)) {
    if (visible_face(std::array<d3::Point, 2>{a, b}, ext) < 0) continue;
    std::snprintf(buf, sizeof buf, "<line class=\"green\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", PX(a),
                  PY(a), PX(b), PY(b));
    out += buf;
  }
  out += "</g>\n";
  // The slice plane's trace on the visible faces it crosses.
  out += "<g stroke=\"#d02020\" stroke-width=\"1.5\" stroke-dasharray=\"6 4\">\n";
  for (const VisibleFace& vf : kVisible) {
    if (vf.axis == slice.axis) continue;
    const int t = 3 - vf.axis - slice.axis;
    std::array<std::int64_t, 3> p{}, q{};
    p[static_cast<std::size_t>(vf.axis)] = q[static_cast<std::size_t>(vf.axis)] =
        vf.far ? ext[static_cast<std::size_t>(vf.axis)] : 0;
    p[sa] = q[sa] = slice.value;
    q[static_cast<std::size_t>(t)] = ext[static_cast<std::size_t>(t)];
    const d3::Point P{p[0], p[1], p[2]}, Q{q[0], q[1], q[2]};
    std::snprintf(buf, sizeof buf, "<line class=\"slice-trace\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n",
                  PX(P), PY(P), PX(Q), PY(Q));
    out += buf;
  }
  out += "</g>\n";

  // Right panel: the slice.
  const std::vector<d3::Point> leaves = sliced_leaves(g, slice);
  int finest = 0;
  for (const auto& [c, l] : g.level) finest = std::max(finest, std::clamp(l, 0, g.size.L));
  const double cell_px = static_cast<double>(d3::cell_side(g.size, finest)) * scale;
  out += "<g stroke=\"#333333\" stroke-width=\"0.8\">\n";
  for (const d3::Point& c : leaves) {
    const std::int64_t h = d3::cell_side(g.size, g.level_of(c)) / 2;
    const std::int64_t u = coord(c, ua), v = coord(c, va);
    std::snprintf(buf, sizeof buf,
                  "<rect class=\"leaf\" x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"%s\"/>\n",
                  SX(u - h), SY(v + h), static_cast<double>(2 * h) * scale, static_cast<double>(2 * h) * scale,
                  shade(g.level_of(c), 1.0).c_str());
    out += buf;
  }
  out += "</g>\n<g>\n";
  const double center_px = std::clamp(cell_px / 8, 1.5, 5.0);
  for (const d3::Point& c : leaves) {
    if (coord(c, slice.axis) != slice.value) continue;
    std::snprintf(buf, sizeof buf,
                  "<rect class=\"center\" x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"#c03030\"/>\n",
                  SX(coord(c, ua)) - center_px / 2, SY(coord(c, va)) - center_px / 2, center_px, center_px);
    out += buf;
  }
  const double r_node = std::clamp(cell_px / 10, 1.5, 4.0), r_ring = std::clamp(cell_px / 5, 3.0, 8.0);
  std::size_t nodes = 0, junctions = 0;
  for (const d3::Point& n : g.N) {
    if (coord(n, slice.axis) != slice.value) continue;
    ++nodes;
    const double x = SX(coord(n, ua)), y = SY(coord(n, va));
    std::snprintf(buf, sizeof buf, "<circle class=\"node\" cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"#1f7a1f\"/>\n", x,
                  y, r_node);
    out += buf;
    const std::size_t deg = g.nbr(n).size();
    if (deg == 3 || deg == 5 || deg == 6 || deg == 7) {
      ++junctions;
      std::snprintf(buf, sizeof buf,
                    "<circle class=\"junction\" cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"none\" stroke=\"#d02020\" "
                    "stroke-width=\"%.2f\"/>\n",
                    x, y, r_ring, r_ring / 3);
      out += buf;
    }
  }
  out += "</g>\n";

  // Panel headings, legend and summary.
  const std::string font = "font-family=\"sans-serif\" font-size=\"13\"";
  out += io::text_start(margin, margin + 14, font) + std::to_string(drawn) + " of " + std::to_string(boundary.size()) +
         " boundary triangles: the faces y = 0, z = " + std::to_string(ext[2]) + ", x = " + std::to_string(ext[0]) +
         "</text>\n";
  out += io::text_start(sx0, margin + 14, font) + "slice " + axis_name(slice.axis) + " = " +
         std::to_string(slice.value) + ": " + std::to_string(leaves.size()) + " leaves, " + std::to_string(nodes) +
         " nodes, " + std::to_string(junctions) + " junctions (" + axis_name(ua) + " right, " + axis_name(va) +
         " up)</text>\n";
  const double foot = top + panel_h + 20;
  std::map<int, std::size_t> per_level;
  for (const auto& [c, l] : g.level) ++per_level[l];
  std::string levels;
  double lx = margin;
  out += "<g stroke=\"#333333\" stroke-width=\"0.6\">\n";
  for (const auto& [l, n] : per_level) {
    levels += (levels.empty() ? "" : ", ") + std::string("level ") + std::to_string(l) + ": " + std::to_string(n);
    out += io::legend_entry(lx, foot, shade(l, 1.0), "level " + std::to_string(l), font);
    lx += 80;
  }
  out += "</g>\n";
  out += io::text_start(margin, foot + 20, font) + io::xml_escape(title) + ": " + std::to_string(g.C.size()) +
         " cells (" + levels + "), " + std::to_string(g.N.size()) + " nodes, " + std::to_string(tets.size()) +
         " tetrahedra.</text>\n";
  out += io::text_start(margin, foot + 38, font) +
         "Fill: level of the leaf; thick green: leaf cube edges; dashed red: the slice; dots: nodes on the slice; "
         "red rings: junctions.</text>\n";
  out += io::svg_end();
  return out;
}

}  // namespace bccmis
