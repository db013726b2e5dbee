// bccmis stuff INPUT|--shape NAME -o FILE...: a tetrahedral mesh of a closed
// shape by isosurface stuffing on the graded BCC mesh (spec/stuffing.md),
// written as .vtu, .msh or .mesh (the tetrahedra) and .off or .obj (the
// boundary surface), with --stats for counts, volume, Hausdorff distance and
// dihedral angles.
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "bccmis/d3/mesh.h"
#include "bccmis/fast/lattice3.h"
#include "bccmis/stuff/animate.h"
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
    double total = 0, meshing = 0;
    for (const auto& [phase, s] : r.seconds) {
      out += "\"" + phase + "\": " + number(s) + ", ", total += s;
      if (phase != "statistics" && phase != "write") meshing += s;
    }
    return out + "\"meshing\": " + number(meshing) + ", \"total\": " + number(total) + "}}\n";
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

/// "DX,DY,DZ", or 1.5 times the shape's x extent along x when empty.
Vec3 parse_path(const std::string& text, const stuff::Shape& shape) {
  if (text.empty()) {
    const stuff::Bounds b = shape.bounds();
    return {1.5 * (b.hi[0] - b.lo[0]), 0, 0};
  }
  Vec3 d{};
  std::size_t at = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t end = i < 2 ? text.find(',', at) : text.size();
    if (end == std::string::npos) throw InputError("--path '" + text + "': expected DX,DY,DZ");
    const std::string item = text.substr(at, end - at);
    const auto [ptr, ec] = std::from_chars(item.data(), item.data() + item.size(), d[i]);
    if (item.empty() || ec != std::errc() || ptr != item.data() + item.size() || !std::isfinite(d[i]))
      throw InputError("--path '" + text + "': '" + item + "' is not a number");
    at = end + 1;
  }
  return d;
}

/// --animate N -o OUT.pvd: frames 0..N (frame 0 the shape where it is),
/// written as OUT_0000.vtu ... beside the .pvd (spec/stuffing.md S15).
int run_animate(const StuffOptions& o, const std::shared_ptr<const stuff::Shape>& shape, stuff::StuffOptions so) {
  if (o.outputs.size() > 1 || (!o.outputs.empty() && !ends_with(o.outputs[0], ".pvd")))
    throw InputError("--animate writes one .pvd (ParaView's index) with its .vtu frames beside it: give -o FILE.pvd");
  if (o.outputs.empty() && !o.stats) throw InputError("nothing to do: give -o FILE.pvd or --stats");
  const Vec3 path = parse_path(o.path, *shape);
  stuff::Fit fit;
  try {
    fit = stuff::fit_lattice(stuff::swept_bounds(*shape, path), so);
    stuff::check_moving_fit(fit);
  } catch (const stuff::ShapeError& e) {
    throw InputError(e.what());
  }
  const std::string pvd = o.outputs.empty() ? "" : o.outputs[0];
  const std::string stem = pvd.substr(0, pvd.size() - 4);
  const std::string base = stem.substr(stem.find_last_of('/') + 1);
  const auto frame_name = [&](int k) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "_%04d.vtu", k);
    return std::string(buf);
  };
  OutputSet outputs;
  std::string index = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  std::string table =
      o.json ? "{\"frames\": ["
             : "frame refines coarsens leaves restuffed_leaves restuffed_tetrahedra tetrahedra lattice_s stuff_s" +
                   std::string(o.compare ? " scratch_s" : "") + "\n";
  const auto t0 = std::chrono::steady_clock::now();
  stuff::MovingLattice moving(shape, fit, so);
  const double initial = seconds_since(t0);
  double step_total = 0, scratch_total = 0;
  std::size_t ops = 0;
  for (int k = 0; k <= o.animate; ++k) {
    stuff::FrameReport r;
    const Vec3 offset{path[0] * k / o.animate, path[1] * k / o.animate, path[2] * k / o.animate};
    if (k == 0) {
      r.leaves = moving.lattice().cell_count();
      r.lattice_seconds = initial;
    } else {
      r = moving.step(offset);
      step_total += r.lattice_seconds + r.stuff_seconds;
      ops += r.refines + r.coarsens;
    }
    double scratch = 0;
    if (o.compare || o.check) {
      const auto t = std::chrono::steady_clock::now();
      const auto moved = stuff::translated(shape, offset);
      const fast::Lattice3 g = stuff::background_fast(*moved, fit, so);
      const stuff::Stuffed s = stuff::stuff(*moved, fit, g, so);
      scratch = seconds_since(t);
      if (k > 0) scratch_total += scratch;
      if (o.check) {
        if (!(g.to_graph() == moving.lattice().to_graph()))
          throw CheckFailure("frame " + std::to_string(k) +
                             ": the lattice updated locally differs from the one built "
                             "from scratch");
        if (!stuff::same_tetrahedra(s.mesh, moving.stuffed().mesh))
          throw CheckFailure("frame " + std::to_string(k) +
                             ": the mesh stuffed again locally differs from the one stuffed "
                             "from scratch");
        const auto boundary = stuff::boundary_triangles(moving.stuffed().mesh);
        if (auto why = check_stuffed(moving.shape(), fit, moving.stuffed().mesh, boundary))
          throw CheckFailure("frame " + std::to_string(k) + ": " + *why);
      }
    }
    const d3::TetMeshF& mesh = moving.stuffed().mesh;
    if (!pvd.empty()) {
      outputs.add(stem + frame_name(k), [&](std::ostream& out) { d3::write_vtu(out, mesh); });
      index +=
          "    <DataSet timestep=\"" + std::to_string(k) + "\" part=\"0\" file=\"" + base + frame_name(k) + "\"/>\n";
    }
    if (o.json) {
      table += std::string(k ? ", " : "") + "{\"frame\": " + std::to_string(k) +
               ", \"refines\": " + std::to_string(r.refines) + ", \"coarsens\": " + std::to_string(r.coarsens) +
               ", \"leaves\": " + std::to_string(r.leaves) +
               ", \"restuffed_leaves\": " + std::to_string(r.restuffed_leaves) +
               ", \"restuffed_tetrahedra\": " + std::to_string(r.restuffed_tetrahedra) +
               ", \"tetrahedra\": " + std::to_string(mesh.tets.size()) +
               ", \"lattice_seconds\": " + number(r.lattice_seconds) +
               ", \"stuff_seconds\": " + number(r.stuff_seconds) +
               (o.compare ? ", \"scratch_seconds\": " + number(scratch) : "") + "}";
    } else {
      table += std::to_string(k) + " " + std::to_string(r.refines) + " " + std::to_string(r.coarsens) + " " +
               std::to_string(r.leaves) + " " + std::to_string(r.restuffed_leaves) + " " +
               std::to_string(r.restuffed_tetrahedra) + " " + std::to_string(mesh.tets.size()) + " " +
               number(r.lattice_seconds) + " " + number(r.stuff_seconds) + (o.compare ? " " + number(scratch) : "") +
               "\n";
    }
    if (!o.quiet)
      std::cerr << "bccmis stuff: frame " << k << "/" << o.animate << ": " << r.refines << " refines, " << r.coarsens
                << " coarsens, " << mesh.tets.size() << " tetrahedra\n";
  }
  index += "  </Collection>\n</VTKFile>\n";
  if (!pvd.empty()) outputs.add(pvd, index);
  const double mean_step = step_total / o.animate, mean_scratch = scratch_total / o.animate;
  if (o.json) {
    table += "], \"mean_step_seconds\": " + number(mean_step) + ", \"operations\": " + std::to_string(ops);
    if (o.compare)
      table += ", \"mean_scratch_seconds\": " + number(mean_scratch) +
               ", \"speedup\": " + number(mean_step > 0 ? mean_scratch / mean_step : 0);
    table += "}\n";
  } else {
    table += "mean_step_seconds " + number(mean_step) + "\noperations " + std::to_string(ops) + "\n";
    if (o.compare)
      table += "mean_scratch_seconds " + number(mean_scratch) + "\nspeedup " +
               number(mean_step > 0 ? mean_scratch / mean_step : 0) + "\n";
  }
  if (o.stats) outputs.add("-", table);
  outputs.commit();
  return kExitOk;
}

}  // namespace

int run(const StuffOptions& o) {
  if (o.animate == 0) {
    for (const std::string& path : o.outputs) check_stuff_path(path);
    if (o.outputs.empty() && !o.stats)
      throw InputError("nothing to do: give -o FILE (.vtu, .msh, .mesh, .off, .obj) or --stats");
  }
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
  if (o.animate > 0) return run_animate(o, shape, so);
  if (!o.path.empty() || o.compare) throw InputError("--path and --compare apply with --animate");
  stuff::Fit fit;
  try {
    fit = stuff::fit_lattice(shape->bounds(), so);
  } catch (const stuff::ShapeError& e) {
    throw InputError(e.what());
  }
  so.max_level = fit.size.L;
  progress(r.shape + ": lattice " + std::to_string(fit.size.W) + " x " + std::to_string(fit.size.H) + " x " +
           std::to_string(fit.size.D) + ", max level " + std::to_string(fit.size.L) + ", finest side " + number(fit.h));
  // spec/stuffing.md S3-S9 on the fast lattice, or on the reference with --impl reference.
  stuff::PhaseTimes times;
  auto t = std::chrono::steady_clock::now();
  const stuff::Stuffed s = [&] {
    if (o.impl == "reference") {
      const d3::Graph3 g = stuff::background(*shape, fit, so);
      times.lattice = seconds_since(t);
      r.leaves = g.C.size();
      progress(std::to_string(r.leaves) + " leaves (" + number(times.lattice) + " s)");
      return stuff::stuff(*shape, fit, g, so, &times);
    }
    const fast::Lattice3 g = stuff::background_fast(*shape, fit, so);
    times.lattice = seconds_since(t);
    r.leaves = g.cell_count();
    progress(std::to_string(r.leaves) + " leaves (" + number(times.lattice) + " s)");
    return stuff::stuff(*shape, fit, g, so, &times);
  }();
  for (const auto& [phase, seconds] :
       {std::pair{"lattice", times.lattice}, std::pair{"mesh", times.mesh}, std::pair{"cut", times.cut},
        std::pair{"warp", times.warp}, std::pair{"stencils", times.stencils}})
    r.seconds.emplace_back(phase, seconds);
  progress(std::to_string(s.mesh.tets.size()) + " tetrahedra (" + number(times.total() - times.lattice) + " s)");
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
