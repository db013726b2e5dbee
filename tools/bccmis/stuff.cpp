// bccmis stuff INPUT|--shape NAME -o FILE...: a tetrahedral mesh of a closed
// shape by isosurface stuffing on the graded BCC mesh (spec/stuffing.md),
// written as .vtu, .msh or .mesh (the tetrahedra) and .off or .obj (the
// boundary surface), with --stats for counts, volume, Hausdorff distance and
// dihedral angles.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "bccmis/d3/mesh.h"
#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/stuff.h"
#include "commands.h"
#include "io.h"
#if BCCMIS_HAVE_STUFF_SURFACE
#include "bccmis/stuff/surface.h"
#endif

namespace bccmis::cli {

namespace {

using stuff::Vec3;

bool ends_with(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool is_surface_path(const std::string& path) { return ends_with(path, ".off") || ends_with(path, ".obj"); }

void check_stuff_path(const std::string& path) {
  if (path == "-") throw InputError("output '-': a mesh is written to a file whose extension names the format");
  if (!is_surface_path(path) && !ends_with(path, ".vtu") && !ends_with(path, ".msh") && !ends_with(path, ".mesh"))
    throw InputError("output '" + path +
                     "': unknown format; the extension names it: .vtu, .msh, .mesh (tetrahedra), .off, .obj "
                     "(boundary surface)");
}

std::shared_ptr<const stuff::Shape> load_shape(const StuffOptions& o) {
  try {
    if (!o.shape.empty() && !o.input.empty()) throw InputError("give either an input mesh or --shape, not both");
    if (!o.shape.empty()) return stuff::make_builtin(o.shape);
    if (o.input.empty()) throw InputError("nothing to mesh: give an input mesh (.off, .obj, .stl) or --shape NAME");
#if BCCMIS_HAVE_STUFF_SURFACE
    return stuff::load_surface(o.input);
#else
    throw InputError(o.input + ": this build has no CGAL, so it reads no meshes; use --shape");
#endif
  } catch (const stuff::ShapeError& e) {
    throw InputError(e.what());
  }
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// spec/stuffing.md S13: the Hausdorff distance, sampled both ways.
struct Hausdorff {
  double from_boundary = 0;  ///< max |f| over 7 points of every boundary triangle
  double from_surface = -1;  ///< max distance of 20,000 surface samples to the boundary (-1: not computed)
};

Hausdorff hausdorff(const stuff::Shape& shape, const d3::TetMeshF& mesh,
                    const std::vector<std::array<std::uint32_t, 3>>& boundary) {
  Hausdorff h;
  for (const auto& t : boundary) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const auto mix = [](const Vec3& x, const Vec3& y, const Vec3& z, double u, double v, double w) {
      return Vec3{u * x[0] + v * y[0] + w * z[0], u * x[1] + v * y[1] + w * z[1], u * x[2] + v * y[2] + w * z[2]};
    };
    for (const Vec3& p : {a, b, c, mix(a, b, c, 0.5, 0.5, 0), mix(a, b, c, 0, 0.5, 0.5), mix(a, b, c, 0.5, 0, 0.5),
                          mix(a, b, c, 1.0 / 3, 1.0 / 3, 1.0 / 3)})
      h.from_boundary = std::max(h.from_boundary, std::abs(shape.signed_distance(p)));
  }
#if BCCMIS_HAVE_STUFF_SURFACE
  if (!boundary.empty())
    h.from_surface = stuff::max_distance_to_triangles(shape.sample_surface(20000, 1), mesh.vertices, boundary);
#endif
  return h;
}

std::string number(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

struct Report {
  std::string shape;
  std::size_t leaves = 0, lattice_tetrahedra = 0, cut_points = 0, warped = 0;
  stuff::StuffQuality q;
  std::size_t vertices = 0, tetrahedra = 0;
  double shape_volume = 0;
  Hausdorff h;
  std::vector<std::pair<std::string, double>> seconds;
};

std::string stats_text(const Report& r, bool json) {
  const double rel = (r.q.volume - r.shape_volume) / r.shape_volume;
  const double below = r.tetrahedra ? static_cast<double>(r.q.below10) / static_cast<double>(r.tetrahedra) : 0;
  const double hmax = std::max(r.h.from_boundary, r.h.from_surface);
  std::string out;
  if (json) {
    out = "{\"shape\": \"" + r.shape + "\", \"leaves\": " + std::to_string(r.leaves) +
          ", \"lattice_tetrahedra\": " + std::to_string(r.lattice_tetrahedra) +
          ", \"cut_points\": " + std::to_string(r.cut_points) + ", \"warped\": " + std::to_string(r.warped) +
          ", \"vertices\": " + std::to_string(r.vertices) + ", \"tetrahedra\": " + std::to_string(r.tetrahedra) +
          ", \"boundary_triangles\": " + std::to_string(r.q.boundary_triangles) +
          ", \"volume\": " + number(r.q.volume) + ", \"shape_volume\": " + number(r.shape_volume) +
          ", \"volume_rel_error\": " + number(rel) +
          ", \"hausdorff\": {\"from_boundary\": " + number(r.h.from_boundary) +
          ", \"from_surface\": " + (r.h.from_surface < 0 ? std::string("null") : number(r.h.from_surface)) +
          ", \"max\": " + number(hmax) + "}, \"min_dihedral\": " + number(r.q.min_dihedral) +
          ", \"max_dihedral\": " + number(r.q.max_dihedral) + ", \"below10\": " + number(below) +
          ", \"dihedral_histogram\": {";
    for (std::size_t k = 0; k < r.q.histogram.size(); ++k)
      out += (k ? ", \"" : "\"") + std::to_string(15 * k) + "\": " + std::to_string(r.q.histogram[k]);
    out += "}, \"seconds\": {";
    double total = 0;
    for (const auto& [phase, s] : r.seconds) out += "\"" + phase + "\": " + number(s) + ", ", total += s;
    return out + "\"total\": " + number(total) + "}}\n";
  }
  out = "shape " + r.shape + "\nleaves " + std::to_string(r.leaves) + "\nlattice_tetrahedra " +
        std::to_string(r.lattice_tetrahedra) + "\ncut_points " + std::to_string(r.cut_points) + "\nwarped " +
        std::to_string(r.warped) + "\nvertices " + std::to_string(r.vertices) + "\ntetrahedra " +
        std::to_string(r.tetrahedra) + "\nboundary_triangles " + std::to_string(r.q.boundary_triangles) + "\nvolume " +
        number(r.q.volume) + "\nshape_volume " + number(r.shape_volume) + "\nvolume_rel_error " + number(rel) +
        "\nhausdorff_from_boundary " + number(r.h.from_boundary) + "\nhausdorff_from_surface " +
        (r.h.from_surface < 0 ? std::string("-") : number(r.h.from_surface)) + "\nhausdorff " + number(hmax) +
        "\nmin_dihedral " + number(r.q.min_dihedral) + "\nmax_dihedral " + number(r.q.max_dihedral) + "\nbelow10 " +
        number(below) + "\n";
  for (std::size_t k = 0; k < r.q.histogram.size(); ++k)
    if (r.q.histogram[k] != 0)
      out += "dihedral_" + std::to_string(15 * k) + " " + std::to_string(r.q.histogram[k]) + "\n";
  for (const auto& [phase, s] : r.seconds) out += "seconds_" + phase + " " + number(s) + "\n";
  return out;
}

/// --check: spec/stuffing.md S7, S12 on what is written: every tetrahedron
/// positively oriented (exactly), every triangle in at most two tetrahedra,
/// the boundary closed (S11) and on the surface (within 1e-9 of the finest side).
std::optional<std::string> check_stuffed(const stuff::Shape& shape, const stuff::Fit& fit, const d3::TetMeshF& m,
                                         const std::vector<std::array<std::uint32_t, 3>>& boundary) {
  for (std::size_t i = 0; i < m.tets.size(); ++i) {
    const auto& t = m.tets[i];
    if (stuff::orientation(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], m.vertices[t[3]]) != 1)
      return "tetrahedron " + std::to_string(i) + " is not positively oriented";
  }
  std::map<std::array<std::uint32_t, 3>, int> faces;
  for (const auto& t : m.tets)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<std::uint32_t, 3> f{};
      for (int i = 0, n = 0; i < 4; ++i)
        if (i != skip) f[static_cast<std::size_t>(n++)] = t[static_cast<std::size_t>(i)];
      std::sort(f.begin(), f.end());
      if (++faces[f] > 2)
        return "the triangle (" + std::to_string(f[0]) + ", " + std::to_string(f[1]) + ", " + std::to_string(f[2]) +
               ") is in more than two tetrahedra";
    }
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& t : boundary)
    for (std::size_t i = 0; i < 3; ++i) {
      ++edges[{t[i], t[(i + 1) % 3]}];
      if (std::abs(shape.signed_distance(m.vertices[t[i]])) > 1e-9 * fit.h)
        return "boundary vertex " + std::to_string(t[i]) + " is off the surface";
    }
  // Closed: every edge is crossed as often in one direction as in the other
  // (once each where the boundary is a manifold; thin parts of a shape at a
  // coarse level may meet along an edge, which then has two of each).
  for (const auto& [e, n] : edges)
    if (const auto back = edges.find({e.second, e.first}); back == edges.end() || back->second != n)
      return "the boundary is not closed at the edge (" + std::to_string(e.first) + ", " + std::to_string(e.second) +
             ")";
  return std::nullopt;
}

}  // namespace

int run(const StuffOptions& o) {
  for (const std::string& path : o.outputs) check_stuff_path(path);
  if (o.outputs.empty() && !o.stats)
    throw InputError("nothing to do: give -o FILE (.vtu, .msh, .mesh, .off, .obj) or --stats");
  const auto progress = [&](const std::string& what) {
    if (!o.quiet) std::cerr << "bccmis stuff: " << what << std::endl;
  };
  const auto t0 = std::chrono::steady_clock::now();
  const std::shared_ptr<const stuff::Shape> shape = load_shape(o);
  Report r;
  r.seconds.emplace_back("input", seconds_since(t0));
  r.shape = shape->describe();
  stuff::StuffOptions so;
  so.max_level = o.max_level;
  so.min_level = o.min_level;
  so.cells = o.cells;
  if (o.size > 0) so.size = o.size;
  stuff::Fit fit;
  try {
    fit = stuff::fit_lattice(shape->bounds(), so);
  } catch (const stuff::ShapeError& e) {
    throw InputError(e.what());
  }
  so.max_level = fit.size.L;
  progress(r.shape + ": lattice " + std::to_string(fit.size.W) + " x " + std::to_string(fit.size.H) + " x " +
           std::to_string(fit.size.D) + ", max level " + std::to_string(fit.size.L) + ", finest side " + number(fit.h));
  auto t = std::chrono::steady_clock::now();
  const d3::Graph3 g = stuff::background(*shape, fit, so);
  r.seconds.emplace_back("lattice", seconds_since(t));
  r.leaves = g.C.size();
  progress(std::to_string(r.leaves) + " leaves (" + number(r.seconds.back().second) + " s)");
  t = std::chrono::steady_clock::now();
  const stuff::Stuffed s = stuff::stuff(*shape, fit, g, so);
  r.seconds.emplace_back("stuffing", seconds_since(t));
  progress(std::to_string(s.mesh.tets.size()) + " tetrahedra (" + number(r.seconds.back().second) + " s)");
  r.lattice_tetrahedra = s.lattice_tetrahedra;
  r.cut_points = s.cut_points;
  r.warped = s.warped;
  r.vertices = s.mesh.vertices.size();
  r.tetrahedra = s.mesh.tets.size();
  r.shape_volume = shape->volume();

  t = std::chrono::steady_clock::now();
  const auto boundary = stuff::boundary_triangles(s.mesh);
  if (o.check)
    if (auto why = check_stuffed(*shape, fit, s.mesh, boundary)) throw CheckFailure(r.shape + ": " + *why);
  if (o.stats) {
    r.q = stuff::quality(s.mesh);
    r.h = hausdorff(*shape, s.mesh, boundary);
  }
  r.seconds.emplace_back("statistics", seconds_since(t));

  t = std::chrono::steady_clock::now();
  OutputSet outputs;
  for (const std::string& path : o.outputs) {
    if (ends_with(path, ".vtu")) outputs.add(path, [&](std::ostream& out) { d3::write_vtu(out, s.mesh); });
    if (ends_with(path, ".msh")) outputs.add(path, [&](std::ostream& out) { d3::write_msh(out, s.mesh); });
    if (ends_with(path, ".mesh")) outputs.add(path, [&](std::ostream& out) { d3::write_medit(out, s.mesh); });
    if (ends_with(path, ".off")) outputs.add(path, [&](std::ostream& out) { stuff::write_off(out, s.mesh, boundary); });
    if (ends_with(path, ".obj")) outputs.add(path, [&](std::ostream& out) { stuff::write_obj(out, s.mesh, boundary); });
  }
  r.seconds.emplace_back("write", seconds_since(t));
  if (o.stats) outputs.add("-", stats_text(r, o.json));
  outputs.commit();
  if (!o.quiet && !o.outputs.empty())
    std::cerr << "bccmis stuff: " << r.vertices << " vertices, " << r.tetrahedra << " tetrahedra written to "
              << o.outputs.size() << " file" << (o.outputs.size() == 1 ? "" : "s") << "\n";
  return kExitOk;
}

}  // namespace bccmis::cli
