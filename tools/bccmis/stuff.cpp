// bccmis stuff INPUT|--shape NAME -o FILE...: a tetrahedral mesh of a closed
// shape by isosurface stuffing (spec/stuffing.md), written as .vtu, .msh or
// .mesh (the tetrahedra) and .off or .obj (the boundary surface), with
// --stats for counts, volume and dihedral angles (--hausdorff: also the
// sampled Hausdorff distance). The
// library does the work (bccmis/stuff/mesh_shape.h, animate_shape.h); this
// file parses, calls and prints.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "bccmis/io/obj.h"
#include "bccmis/io/off.h"
#include "bccmis/io/pvd.h"
#include "bccmis/io/vtu.h"
#include "bccmis/json_writer.h"
#include "bccmis/stuff/animate_shape.h"
#include "bccmis/stuff/mesh_shape.h"
#include "bccmis/stuff/statistics_json.h"
#include "commands.h"
#include "io.h"
#include "stuff_input.h"

namespace bccmis::cli {

namespace {

using stuff::Vec3;

bool is_surface_path(const std::string& path) { return ends_with(path, ".off") || ends_with(path, ".obj"); }

void check_stuff_path(const std::string& path) {
  if (path == "-") throw InputError("output '-': a mesh is written to a file whose extension names the format");
  if (!is_surface_path(path) && !ends_with(path, ".vtu") && !ends_with(path, ".msh") && !ends_with(path, ".mesh"))
    throw InputError("output '" + path +
                     "': unknown format; the extension names it: .vtu, .msh, .mesh (tetrahedra), .off, .obj "
                     "(boundary surface)");
}

std::string number(double x) { return JsonWriter::number(x); }

/// The library's progress lines on stderr, unless --quiet.
stuff::Progress progress_of(const StuffOptions& o) {
  if (o.quiet) return {};
  return [](std::string_view what) { std::cerr << "bccmis stuff: " << what << std::endl; };
}

/// The faces of the first few instances of a flaw: "3+4 7+9".
std::string instances_text(const stuff::SoupFlaw& f) {
  std::string out;
  for (const auto& faces : f.first) {
    out += out.empty() ? "" : " ";
    for (std::size_t i = 0; i < faces.size(); ++i) out += (i == 0 ? "" : "+") + std::to_string(faces[i]);
  }
  return out;
}
std::string soup_text(const stuff::SoupReport& r) {
  std::string out = "soup_faces " + std::to_string(r.faces) + "\nsoup_flaws " + std::to_string(r.flaw_count()) + "\n";
  const auto item = [&](const std::string& key, const stuff::SoupFlaw& f) {
    out += "soup_" + key + " " + std::to_string(f.count) + "\n";
    if (f.count > 0) out += "soup_" + key + "_first " + instances_text(f) + "\n";
  };
  for (std::size_t k = 0; k < stuff::SoupReport::kKinds; ++k)
    item(stuff::SoupReport::key(static_cast<stuff::SoupReport::Kind>(k)), r.flaws[k]);
  out += "soup_components " + std::to_string(r.components) + "\nsoup_inward_components " +
         std::to_string(r.inward_components) + "\nsoup_flipped_faces " + std::to_string(r.flipped_faces) +
         "\nsoup_dropped_faces " + std::to_string(r.dropped_faces) + "\nsoup_welded_vertices " +
         std::to_string(r.welded_vertices) + "\n";
  item("bad_normals", r.bad_normals);
  return out;
}

/// --stats: S13's report as `name value` lines, or one JSON object.
std::string stats_text(const std::string& shape, const stuff::Meshed& m, const stuff::PhaseSeconds& seconds,
                       bool json) {
  const stuff::Statistics& s = *m.statistics;
  const stuff::StuffQuality& q = s.quality;
  const stuff::Hausdorff& h = s.hausdorff;
  if (json) return stuff::statistics_json(shape, m, seconds) + "\n";
  std::string out = "shape " + shape + "\n";
  for (const auto& [name, n] : stuff::statistics_counts(m)) out += std::string(name) + " " + std::to_string(n) + "\n";
  out += "volume " + number(q.volume) + "\nshape_volume " + number(s.shape_volume) + "\nvolume_rel_error " +
         number(s.volume_rel_error()) + "\n";
  if (h.computed)  // --hausdorff
    out += "hausdorff_from_boundary " + number(h.from_boundary) + "\nhausdorff_from_surface " +
           (h.from_surface < 0 ? std::string("-") : number(h.from_surface)) + "\nhausdorff " + number(h.max()) +
           "\nhausdorff_boundary_points " + std::to_string(h.boundary_points) + "\nhausdorff_surface_samples " +
           std::to_string(h.surface_samples) + "\n";
  out += "min_dihedral " + number(q.min_dihedral) + "\nmax_dihedral " + number(q.max_dihedral) + "\nbelow10 " +
         number(s.below10()) + "\n";
  for (std::size_t k = 0; k < q.histogram.size(); ++k)
    if (q.histogram[k] != 0) out += "dihedral_" + std::to_string(15 * k) + " " + std::to_string(q.histogram[k]) + "\n";
  out += "boundary_euler " + std::to_string(m.topology.boundary_euler) + "\n";
  for (const std::string& warning : m.warnings) out += "warning " + warning + "\n";
  if (m.features)  // S33
    out += "feature_angle " + number(m.features->angle) + "\nfeature_distance " + number(m.features->distance) + "\n";
  if (m.soup) out += soup_text(*m.soup);
  for (const auto& [phase, t] : seconds) out += "seconds_" + phase + " " + number(t) + "\n";
  return out;
}

/// "DX,DY,DZ", or the library's default path when empty.
Vec3 parse_path(const std::string& text, const stuff::Shape& shape) {
  if (text.empty()) return stuff::default_path(shape);
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
int run_animate(const StuffOptions& o, const std::shared_ptr<const stuff::Shape>& shape, stuff::StuffOptions so,
                OutputSet& outputs) {
  if (o.outputs.size() > 1 || (!o.outputs.empty() && !ends_with(o.outputs[0], ".pvd")))
    throw InputError("--animate writes one .pvd (ParaView's index) with its .vtu frames beside it: give -o FILE.pvd");
  if (o.outputs.empty() && !o.stats) throw InputError("nothing to do: give -o FILE.pvd or --stats");
  if (o.hausdorff) throw InputError("--hausdorff applies without --animate (a frame's statistics have no distance)");
  if (o.features || o.feature_angle >= 0) throw InputError("--features and --feature-angle apply without --animate");
  stuff::AnimateSettings settings;
  settings.lattice = so;
  settings.frames = o.animate;
  settings.path = parse_path(o.path, *shape);
  settings.compare = o.compare;
  settings.check = o.check;
  const std::string pvd = o.outputs.empty() ? "" : o.outputs[0];
  const std::string stem = pvd.substr(0, pvd.size() - 4);
  const std::string base = stem.substr(stem.find_last_of('/') + 1);
  const auto frame_name = [&](int k) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "_%04d.vtu", k);
    return std::string(buf);
  };
  if (!pvd.empty()) {  // every file created before the first frame is made
    for (int k = 0; k <= o.animate; ++k) outputs.open(stem + frame_name(k));
    outputs.open(pvd);
  }
  std::vector<std::pair<int, std::string>> frames;  // the .pvd index: timestep, file
  JsonWriter json;
  json.begin_object().key("frames").begin_array();
  std::string table =
      "frame refines coarsens leaves restuffed_leaves restuffed_tetrahedra tetrahedra lattice_s stuff_s" +
      std::string(o.compare ? " scratch_s" : "") + "\n";
  const auto on_frame = [&](const stuff::Frame& f) {
    const int k = f.index;
    const stuff::FrameReport& r = f.report;
    const d3::TetMeshF& mesh = *f.mesh;
    if (!pvd.empty()) {
      outputs.add(stem + frame_name(k), [&](std::ostream& out) { io::write_vtu(out, mesh, encoding(o)); });
      frames.emplace_back(k, base + frame_name(k));
    }
    json.begin_object()
        .member("frame", k)
        .member("refines", r.refines)
        .member("coarsens", r.coarsens)
        .member("leaves", r.leaves)
        .member("restuffed_leaves", r.restuffed_leaves)
        .member("restuffed_tetrahedra", r.restuffed_tetrahedra)
        .member("tetrahedra", mesh.tets.size())
        .member("lattice_seconds", r.lattice_seconds)
        .member("stuff_seconds", r.stuff_seconds);
    if (o.compare) json.member("scratch_seconds", f.scratch_seconds);
    json.end_object();
    table += std::to_string(k) + " " + std::to_string(r.refines) + " " + std::to_string(r.coarsens) + " " +
             std::to_string(r.leaves) + " " + std::to_string(r.restuffed_leaves) + " " +
             std::to_string(r.restuffed_tetrahedra) + " " + std::to_string(mesh.tets.size()) + " " +
             number(r.lattice_seconds) + " " + number(r.stuff_seconds) +
             (o.compare ? " " + number(f.scratch_seconds) : "") + "\n";
    if (!o.quiet)
      std::cerr << "bccmis stuff: frame " << k << "/" << o.animate << ": " << r.refines << " refines, " << r.coarsens
                << " coarsens, " << mesh.tets.size() << " tetrahedra\n";
  };
  stuff::AnimationSummary summary;
  try {
    summary = stuff::animate_shape(shape, settings, on_frame, progress_of(o));
  } catch (const stuff::ShapeError& e) {  // S2, S14, S16: refused before any frame is made
    throw InputError(e.what());
  } catch (const stuff::CheckError& e) {
    throw CheckFailure(e.what());
  }
  if (!pvd.empty()) outputs.add(pvd, [&](std::ostream& out) { io::write_pvd(out, frames); });
  json.end_array().member("mean_step_seconds", summary.mean_step_seconds).member("operations", summary.operations);
  table += "mean_step_seconds " + number(summary.mean_step_seconds) + "\noperations " +
           std::to_string(summary.operations) + "\n";
  if (o.compare) {
    json.member("mean_scratch_seconds", summary.mean_scratch_seconds).member("speedup", summary.speedup());
    table += "mean_scratch_seconds " + number(summary.mean_scratch_seconds) + "\nspeedup " + number(summary.speedup()) +
             "\n";
  }
  json.end_object();
  if (o.stats) outputs.add("-", o.json ? json.str() + "\n" : table);
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
  // The outputs' temporaries are created before the work (spec/cli.md).
  OutputSet outputs;
  if (o.animate == 0)
    for (const std::string& path : o.outputs) outputs.open(path);
  const auto t0 = stuff::Clock::now();
  std::shared_ptr<const stuff::Shape> shape;
  try {
    shape = load_shape(o);
  } catch (const stuff::ShapeError& e) {
    throw InputError(e.what());
  }
  stuff::PhaseSeconds seconds{{"input", stuff::seconds_since(t0)}};
  if (const stuff::SoupReport* r = shape->soup_report(); r && r->flaw_count() > 0 && !o.stats && !o.quiet)
    std::cerr << "bccmis stuff: " << r->file << ": " << r->summary()
              << ": meshed as the solid where the winding number >= 1/2; --strict refuses\n";
  if (const stuff::SoupReport* r = shape->soup_report(); r && r->welded_vertices > 0 && !o.stats && !o.quiet)
    std::cerr << "bccmis stuff: " << r->file << ": " << r->welded_vertices
              << " repeated vertices welded (the coordinates of an earlier vertex)\n";
  stuff::Settings settings;
  settings.lattice.max_level = o.max_level;
  settings.lattice.min_level = o.min_level;
  settings.lattice.cells = o.cells;
  if (o.size > 0) settings.lattice.size = o.size;
  settings.lattice.threads = o.threads;
  if (o.animate > 0) return run_animate(o, shape, settings.lattice, outputs);
  if (!o.path.empty() || o.compare) throw InputError("--path and --compare apply with --animate");
  settings.impl = o.impl == "reference" ? stuff::Impl::reference : stuff::Impl::fast;
  settings.statistics = o.stats;
  settings.hausdorff = o.hausdorff;
  settings.check = o.check;
  settings.strict = o.strict;
  // spec/cli.md: on by default for a triangle-mesh INPUT (S29-S33).
  settings.features.on = (o.features || o.feature_angle >= 0 || !o.input.empty()) && !o.no_features;
  if (o.feature_angle >= 0) settings.features.angle = o.feature_angle;
  if (o.memory_limit_gb > 0) settings.memory_limit = o.memory_limit_gb * 1e9;
  stuff::Meshed m;
  try {
    m = stuff::mesh_shape(*shape, settings, progress_of(o));
  } catch (const stuff::ShapeError& e) {
    throw InputError(e.what());
  } catch (const stuff::CheckError& e) {
    throw CheckFailure(e.what());
  }
  seconds.insert(seconds.end(), m.seconds.begin(), m.seconds.end());
  if (!o.quiet)
    for (const std::string& warning : m.warnings) std::cerr << "bccmis stuff: warning: " << warning << "\n";

  const auto t = stuff::Clock::now();
  const d3::TetMeshF& mesh = m.stuffed.mesh;
  for (const std::string& path : o.outputs) {
    const bool all = o.surface_vertices == "all";
    add_tetrahedra_output(outputs, path, mesh, m.regions, encoding(o));
    if (ends_with(path, ".off"))
      outputs.add(path, [&](std::ostream& out) { io::write_off(out, mesh, m.boundary, all); });
    if (ends_with(path, ".obj"))
      outputs.add(path, [&](std::ostream& out) { io::write_obj(out, mesh, m.boundary, all); });
  }
  seconds.emplace_back("write", stuff::seconds_since(t));
  if (o.stats) outputs.add("-", stats_text(shape->describe(), m, seconds, o.json));
  outputs.commit();
  if (!o.quiet && !o.outputs.empty())
    std::cerr << "bccmis stuff: " << mesh.vertices.size() << " vertices, " << mesh.tets.size()
              << " tetrahedra written to " << o.outputs.size() << " file" << (o.outputs.size() == 1 ? "" : "s") << "\n";
  return kExitOk;
}

}  // namespace bccmis::cli
