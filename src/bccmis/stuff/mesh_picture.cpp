// The pictures of mesh_picture.h: an orthographic view of the boundary with back
// faces culled and the rest painted far to near, and the angle histogram.
#include "bccmis/stuff/mesh_picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

#include "bccmis/io/svg.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

namespace {

using V = std::array<double, 3>;

V sub(const V& a, const V& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V cross(const V& a, const V& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V unit(const V& a) {
  const double n = std::sqrt(dot(a, a));
  return n > 0 ? V{a[0] / n, a[1] / n, a[2] / n} : V{0, 0, 0};
}

const V kEye = unit(kViewDirection);
const V kRight = unit({2, 1, 0});
const V kUp = unit({-1.5, 3, 5});
// The light comes from the viewer's upper left.
const V kLight = unit({kEye[0] - 0.5 * kRight[0] + 0.6 * kUp[0], kEye[1] - 0.5 * kRight[1] + 0.6 * kUp[1],
                       kEye[2] - 0.5 * kRight[2] + 0.6 * kUp[2]});

const char* axis_name(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

// The drawn width of text in the sans-serif font, estimated at 0.6 of the
// font size a character (DejaVu Sans averages less, its digits 0.64).
double text_width(const std::string& s, double font_size) { return 0.6 * font_size * static_cast<double>(s.size()); }

// The words of text in lines no wider than width; a word wider than that
// gets a line of its own.
std::vector<std::string> wrap(const std::string& text, double width, double font_size) {
  std::vector<std::string> lines;
  std::string line;
  for (std::size_t i = 0; i <= text.size();) {
    std::size_t j = text.find(' ', i);
    if (j == std::string::npos) j = text.size();
    const std::string word = text.substr(i, j - i);
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && text_width(longer, font_size) > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = longer;
    }
    i = j + 1;
  }
  lines.push_back(line);
  return lines;
}

// Lines of text, escaped, one <text> each at x, the first baseline at y and
// the next ones step below it.
std::string text_lines(const std::vector<std::string>& lines, double x, double y, double step,
                       const std::string& attributes) {
  std::string out;
  for (std::size_t k = 0; k < lines.size(); ++k)
    out += io::text_start(x, y + step * static_cast<double>(k), attributes) + io::xml_escape(lines[k]) + "</text>\n";
  return out;
}

// The colour of a level (levels above 9 share the last one), scaled by a
// face's brightness.
constexpr int kPalette[10][3] = {{0xd9, 0xd9, 0xd9}, {0xfd, 0xd4, 0x9e}, {0xfd, 0xae, 0x6b}, {0xa1, 0xd9, 0x9b},
                                 {0x6b, 0xae, 0xd6}, {0x9e, 0x9a, 0xc8}, {0xf7, 0x68, 0xa1}, {0x41, 0xb6, 0xc4},
                                 {0xe3, 0x1a, 0x1c}, {0x80, 0x80, 0x80}};
std::string colour(int level, double brightness) {
  const auto l = static_cast<std::size_t>(std::clamp(level, 0, 9));
  const auto channel = [&](std::size_t i) {
    return static_cast<int>(std::clamp(std::lround(kPalette[l][i] * brightness), 0L, 255L));
  };
  return io::hex_colour(channel(0), channel(1), channel(2));
}

// A boundary triangle facing the viewer, ready to draw.
struct Face {
  std::array<std::uint32_t, 3> v;
  double depth;  // the centroid's distance towards the viewer
  int level;
  double brightness;
};

// The faces of `mesh` (its tetrahedra `keep` only) facing the viewer, far
// to near; `boundary` is set to the number of boundary triangles.
std::vector<Face> visible_faces(const d3::TetMeshF& mesh, const std::vector<bool>& keep, std::size_t& boundary) {
  d3::TetMeshF part;
  part.vertices = mesh.vertices;
  std::vector<int> tet_level;
  for (std::size_t i = 0; i < mesh.tets.size(); ++i)
    if (keep[i]) {
      part.tets.push_back(mesh.tets[i]);
      tet_level.push_back(i < mesh.level.size() ? mesh.level[i] : 0);
    }
  // The level of a boundary triangle: that of the one tetrahedron holding it.
  std::map<std::array<std::uint32_t, 3>, int> level_of;
  for (std::size_t i = 0; i < part.tets.size(); ++i)
    for (std::size_t skip = 0; skip < 4; ++skip) {
      std::array<std::uint32_t, 3> key{};
      for (std::size_t j = 0, n = 0; j < 4; ++j)
        if (j != skip) key[n++] = part.tets[i][j];
      std::sort(key.begin(), key.end());
      level_of[key] = tet_level[i];
    }
  const auto tris = boundary_triangles(part);
  boundary = tris.size();
  std::vector<Face> out;
  for (const auto& t : tris) {
    const V& a = mesh.vertices[t[0]];
    const V& b = mesh.vertices[t[1]];
    const V& c = mesh.vertices[t[2]];
    const V n = unit(cross(sub(b, a), sub(c, a)));
    if (dot(n, kEye) <= 0) continue;
    std::array<std::uint32_t, 3> key = t;
    std::sort(key.begin(), key.end());
    const V centroid{(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3};
    out.push_back({t, dot(centroid, kEye), level_of[key], 0.55 + 0.45 * std::max(0.0, dot(n, kLight))});
  }
  std::stable_sort(out.begin(), out.end(), [](const Face& x, const Face& y) { return x.depth < y.depth; });
  return out;
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

std::string render_mesh_svg(const d3::TetMeshF& mesh, const std::string& title, const std::optional<CutPlane>& cut) {
  if (cut && (cut->axis < 0 || cut->axis > 2)) throw std::invalid_argument("cut axis must be 0, 1 or 2 (x, y or z)");
  // The picture's extent: every vertex projected.
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const V& p : mesh.vertices) {
    x0 = std::min(x0, dot(p, kRight));
    x1 = std::max(x1, dot(p, kRight));
    y0 = std::min(y0, dot(p, kUp));
    y1 = std::max(y1, dot(p, kUp));
  }
  if (mesh.vertices.empty()) x0 = x1 = y0 = y1 = 0;
  const double panels = cut ? 2 : 1;
  const double box_w = cut ? 460.0 : 620.0, box_h = 520.0;
  const double scale = std::min(box_w / std::max(x1 - x0, 1e-300), box_h / std::max(y1 - y0, 1e-300));
  const double margin = 20, gap = 40, font_size = 13, line = 17;
  const double panel_w = (x1 - x0) * scale, panel_h = (y1 - y0) * scale;
  // A panel's column is wide enough for its title in a few lines.
  const double column = std::max(panel_w, 340.0);
  const double width = std::max(panels * column + (panels - 1) * gap + 2 * margin, 560.0);
  const std::string font = "font-family=\"sans-serif\" font-size=\"13\"";

  // The panels' titles, wrapped to their columns; the pictures start below the longer one.
  std::size_t boundary = 0;
  const std::vector<Face> all = visible_faces(mesh, std::vector<bool>(mesh.tets.size(), true), boundary);
  const std::vector<std::string> all_title =
      wrap(std::to_string(all.size()) + " of " + std::to_string(boundary) + " boundary triangles face the viewer",
           column, font_size);
  std::vector<Face> rest;
  std::vector<std::string> cut_title;
  if (cut) {
    const auto a = static_cast<std::size_t>(cut->axis);
    const bool above = kViewDirection[a] > 0;  // the viewer's side
    std::vector<bool> keep(mesh.tets.size());
    std::size_t removed = 0;
    for (std::size_t i = 0; i < mesh.tets.size(); ++i) {
      double c = 0;
      for (const std::uint32_t v : mesh.tets[i]) c += 0.25 * mesh.vertices[v][a];
      keep[i] = above ? !(c > cut->value) : !(c < cut->value);
      removed += keep[i] ? 0 : 1;
    }
    std::size_t cut_boundary = 0;
    rest = visible_faces(mesh, keep, cut_boundary);
    // In lines of their own: what was removed, which, what is left.
    const std::string c = std::string(axis_name(cut->axis)), at = fmt(cut->value);
    for (const std::string& part :
         {"cut at " + c + " = " + at + ": " + std::to_string(removed) + " tetrahedra removed,",
          "those with centroid " + c + (above ? " > " : " < ") + at + ";",
          std::to_string(rest.size()) + " of " + std::to_string(cut_boundary) + " triangles face the viewer"})
      for (const std::string& l : wrap(part, column, font_size)) cut_title.push_back(l);
  }
  const double top = margin + 14 + line * static_cast<double>(std::max(all_title.size(), cut_title.size()) - 1) + 16;

  char buf[320];
  std::string out;
  out += io::svg_title(title);

  const auto panel = [&](const std::vector<Face>& faces, double left, const char* cls) {
    out += "<g stroke=\"#404040\" stroke-width=\"0.4\" stroke-linejoin=\"round\">\n";
    for (const Face& f : faces) {
      out += "<polygon class=\"";
      out += cls;
      out += "\" data-level=\"" + std::to_string(f.level) + "\" points=\"";
      for (std::size_t k = 0; k < 3; ++k) {
        const V& p = mesh.vertices[f.v[k]];
        std::snprintf(buf, sizeof buf, "%s%.1f,%.1f", k ? " " : "", left + (dot(p, kRight) - x0) * scale,
                      top + (y1 - dot(p, kUp)) * scale);
        out += buf;
      }
      out += "\" fill=\"" + colour(f.level, f.brightness) + "\"/>\n";
    }
    out += "</g>\n";
  };

  panel(all, margin, "tri");
  out += text_lines(all_title, margin, margin + 14, line, font);
  if (cut) {
    const double left = margin + column + gap;
    panel(rest, left, "cut-tri");
    out += text_lines(cut_title, left, margin + 14, line, font);
  }

  // Legend and summary.
  std::map<int, std::size_t> per_level;
  for (std::size_t i = 0; i < mesh.tets.size(); ++i) ++per_level[i < mesh.level.size() ? mesh.level[i] : 0];
  // Legend entries side by side, as wide as their text, in rows across the picture.
  double foot = top + panel_h + 24;
  double lx = margin;
  out += "<g stroke=\"#333333\" stroke-width=\"0.6\">\n";
  for (const auto& [l, n] : per_level) {
    const std::string label = "level " + std::to_string(l) + ": " + std::to_string(n);
    const double entry = 16 + text_width(label, font_size);
    if (lx > margin && lx + entry > width - margin) {
      lx = margin;
      foot += line + 4;
    }
    out += io::legend_entry(lx, foot, colour(l, 1.0), label, font);
    lx += std::max(110.0, entry + 24);
  }
  out += "</g>\n";
  std::vector<std::string> summary;
  for (const std::string& part :
       {title + ": " + std::to_string(mesh.vertices.size()) + " vertices, " + std::to_string(mesh.tets.size()) +
            " tetrahedra;",
        std::string("fill: the level of the tetrahedron (tetrahedra per level), shaded by the normal")})
    for (const std::string& l : wrap(part, width - 2 * margin, font_size)) summary.push_back(l);
  out += text_lines(summary, margin, foot + 22, line, font);
  out += io::svg_end();
  const double height = foot + 22 + line * static_cast<double>(summary.size() - 1) + 34;
  return io::svg_start(width, height) + out;
}

AngleHistogram angle_histogram(const d3::TetMeshF& mesh) {
  AngleHistogram h;
  h.min = mesh.tets.empty() ? 0 : 180;
  for (const auto& t : mesh.tets) {
    const std::array<V, 4> p{mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]};
    for (const double a : d3::dihedral_angles(p)) {
      ++h.angles;
      h.min = std::min(h.min, a);
      h.max = std::max(h.max, a);
      const double k = std::floor((a + 1e-9) / 5);
      ++h.bins[static_cast<std::size_t>(std::clamp(k, 0.0, 35.0))];
    }
  }
  return h;
}

std::string render_histogram_svg(const d3::TetMeshF& mesh, const std::string& title) {
  const AngleHistogram h = angle_histogram(mesh);
  std::size_t most = 1;
  for (const std::size_t n : h.bins) most = std::max(most, n);
  // A round step for the count axis: 1, 2 or 5 times a power of ten, about 5 ticks.
  double step = 1;
  for (double p = 1;; p *= 10) {
    const double m[3] = {1, 2, 5};
    bool found = false;
    for (const double f : m)
      if (!found && static_cast<double>(most) / (f * p) <= 6) {
        step = f * p;
        found = true;
      }
    if (found) break;
  }
  const double ymax = std::ceil(static_cast<double>(most) / step) * step;
  // The left margin holds the widest count and, left of it, the axis label
  // turned upright; the plot starts below the title's lines.
  const double font_size = 12, bar_w = 17, plot_w = 36 * bar_w, plot_h = 260;
  double widest = 0;
  for (double c = 0; c <= ymax + 0.5 * step; c += step) widest = std::max(widest, text_width(fmt(c), font_size));
  const double left = std::max(70.0, std::ceil(widest + 32)), width = left + plot_w + 30;
  const double label_x = left - widest - 18;
  std::string heading =
      title + ": " + std::to_string(mesh.tets.size()) + " tetrahedra, " + std::to_string(h.angles) + " dihedral angles";
  if (h.angles > 0) {
    char extremes[80];
    std::snprintf(extremes, sizeof extremes, ", min %.2f, max %.2f degrees", h.min, h.max);
    heading += extremes;
  }
  const std::vector<std::string> heading_lines = wrap(heading, width - left - 10, font_size);
  const double top = 50 + 15 * static_cast<double>(heading_lines.size() - 1), height = top + plot_h + 70;
  const auto X = [&](double degrees) { return left + degrees / 180 * plot_w; };
  const auto Y = [&](double count) { return top + plot_h - count / ymax * plot_h; };

  char buf[400];
  std::string out = io::svg_header(width, height, title + ": dihedral angles");
  const std::string font = "font-family=\"sans-serif\" font-size=\"12\"";
  out += text_lines(heading_lines, left, 18, 15, font);
  // Grid and count ticks.
  out += "<g stroke=\"#dddddd\" stroke-width=\"1\">\n";
  for (double c = 0; c <= ymax + 0.5 * step; c += step) {
    std::snprintf(buf, sizeof buf,
                  "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/><text x=\"%.1f\" y=\"%.1f\" %s "
                  "text-anchor=\"end\" stroke=\"none\" fill=\"black\">%s</text>\n",
                  left, Y(c), left + plot_w, Y(c), left - 6, Y(c) + 4, font.c_str(), fmt(c).c_str());
    out += buf;
  }
  out += "</g>\n<g fill=\"#4f86c6\" stroke=\"#25508c\" stroke-width=\"0.8\">\n";
  for (std::size_t k = 0; k < h.bins.size(); ++k) {
    if (h.bins[k] == 0) continue;
    const double n = static_cast<double>(h.bins[k]);
    std::snprintf(buf, sizeof buf,
                  "<rect class=\"bar\" data-bin=\"%zu\" data-count=\"%zu\" x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" "
                  "height=\"%.1f\"><title>[%zu, %zu) degrees: %zu</title></rect>\n",
                  k, h.bins[k], X(5.0 * static_cast<double>(k)), Y(n), bar_w, plot_h - (Y(n) - top), 5 * k, 5 * k + 5,
                  h.bins[k]);
    out += buf;
  }
  out += "</g>\n";
  // Axes, angle ticks every 30 degrees, labels.
  std::snprintf(buf, sizeof buf,
                "<g stroke=\"black\" stroke-width=\"1\"><line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>"
                "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/></g>\n",
                left, top, left, top + plot_h, left, top + plot_h, left + plot_w, top + plot_h);
  out += buf;
  for (int d = 0; d <= 180; d += 30) {
    std::snprintf(buf, sizeof buf,
                  "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"black\"/>"
                  "<text x=\"%.1f\" y=\"%.1f\" %s text-anchor=\"middle\">%d</text>\n",
                  X(d), top + plot_h, X(d), top + plot_h + 5, X(d), top + plot_h + 18, font.c_str(), d);
    out += buf;
  }
  std::snprintf(buf, sizeof buf,
                "<text x=\"%.1f\" y=\"%.1f\" %s text-anchor=\"middle\">dihedral angle (degrees), bins of 5</text>\n"
                "<text x=\"%.1f\" y=\"%.1f\" %s text-anchor=\"middle\" transform=\"rotate(-90 %.1f %.1f)\">"
                "angles per bin</text>\n",
                left + plot_w / 2, top + plot_h + 38, font.c_str(), label_x, top + plot_h / 2, font.c_str(), label_x,
                top + plot_h / 2);
  out += buf;
  // The extremes.
  if (h.angles > 0) {
    for (const auto& [cls, a] : {std::pair<const char*, double>{"min", h.min}, {"max", h.max}}) {
      // The label centred on its line but kept inside the picture.
      std::snprintf(buf, sizeof buf, "%s %.2f", cls, a);
      const double half = text_width(buf, font_size) / 2;
      const double label = std::clamp(X(a), half + 4, width - half - 4);
      std::snprintf(buf, sizeof buf,
                    "<line class=\"%s\" x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#d02020\" "
                    "stroke-width=\"1.5\" stroke-dasharray=\"5 3\"/>"
                    "<text x=\"%.1f\" y=\"%.1f\" %s fill=\"#d02020\" text-anchor=\"middle\">%s %.2f</text>\n",
                    cls, X(a), top - 4, X(a), top + plot_h, label, top - (std::string_view(cls) == "min" ? 22 : 8),
                    font.c_str(), cls, a);
      out += buf;
    }
  }
  out += io::svg_end();
  return out;
}

}  // namespace bccmis::stuff
