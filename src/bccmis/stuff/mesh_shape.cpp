// The stuffing library's entry point (mesh_shape.h): S2-S13 in one call.
#include "bccmis/stuff/mesh_shape.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "bccmis/invariants/d3/feature_conformity.h"
#include "bccmis/invariants/d3/stuffed_mesh.h"
#include "bccmis/json_writer.h"
#include "bccmis/stuff/background_statistics.h"
#include "bccmis/stuff/crease_cuts.h"
#include "bccmis/stuff/memory_estimate.h"
#include "bccmis/stuff/normalisation.h"
#include "bccmis/stuff/stopwatch.h"
#if BCCMIS_HAVE_STUFF_SURFACE
#include "bccmis/stuff/surface.h"
#endif

namespace bccmis::stuff {

namespace {
std::string number(double x) { return JsonWriter::number(x); }

}  // namespace

namespace {

/// S26/S27's hint for a part whose thinnest extent is `e` (`what` names
/// it): "<verdict> (the finest cell side h against the thinnest extent of
/// <what> e); -L N would resolve it", N the first level whose finest cell
/// side is at most e/4, and at least one level finer than `fit`'s.
std::string level_hint(const std::string& verdict, double e, const std::string& what, const Fit& fit) {
  int level = fit.size.L;
  for (double h = fit.h; h > e / 4 && level < 64; h /= 2) ++level;
  return verdict + " (the finest cell side " + number(fit.h) + " against the thinnest extent of " + what + " " +
         number(e) + "); -L " + std::to_string(std::max(level, fit.size.L + 1)) + " would resolve it";
}

std::string level_hint(double e, const std::string& what, const Fit& fit) {
  return level_hint("bad input for this level", e, what, fit);
}

double thinnest_extent(const Bounds& box) {
  double e = box.hi[0] - box.lo[0];
  for (std::size_t i = 1; i < 3; ++i) e = std::min(e, box.hi[i] - box.lo[i]);
  return e;
}

}  // namespace

std::string level_hint(const Bounds& box, const Fit& fit) {
  return level_hint(thinnest_extent(box), "the shape's box", fit);
}

std::vector<std::string> mesh_warnings(const Shape& world, const MeshTopology& t, const Fit& fit) {
  std::vector<std::string> warnings;
  if (const auto want = world.surface_components()) {
    const std::size_t got = t.boundary_components;
    const std::string counts = "the mesh's boundary has " + std::to_string(got) + " component" + (got == 1 ? "" : "s") +
                               " where the shape's surface has " + std::to_string(want->count);
    if (got < want->count)
      throw ShapeError(world.describe() + ": a component is lost: " + counts + ": " +
                       level_hint(want->thinnest, "the thinnest component's box", fit));
    if (got > want->count) warnings.push_back(counts);
  }
  if (t.nonmanifold_edges > 0)
    warnings.push_back("the mesh's boundary has " + std::to_string(t.nonmanifold_edges) +
                       " non-manifold edges (parts meeting along a lattice edge; a finer level separates them)");
  // S26: a mesh made on cells coarser than a quarter of the shape's thinnest extent.
  if (const double e = thinnest_extent(world.bounds()); fit.h > e / 4)
    warnings.push_back(level_hint("the mesh is coarse", e, "the shape's box", fit));
  return warnings;
}

std::string empty_mesh_message(const Shape& shape, const Fit& fit) {
  if (const SoupReport* soup = shape.soup_report(); soup && soup->flaw_count() > 0)
    return soup->file + ": encloses no volume (the winding number is below 1/2 at every lattice vertex); a solid " +
           "thinner than the finest cell side " + number(fit.h) + " needs a level above " + std::to_string(fit.size.L);
  return shape.describe() + ": the mesh is empty: " + level_hint(shape.bounds(), fit);
}

std::unique_ptr<Shape> load_mesh_file(const std::string& path, bool strict, std::optional<io::SurfaceFormat> format) {
#if BCCMIS_HAVE_STUFF_SURFACE
  return strict ? load_surface(path, format) : load_soup(path, format);
#else
  (void)strict, (void)format;
  throw ShapeError(path + ": this build has no CGAL, so it reads no meshes; use --shape");
#endif
}

std::optional<std::string> find_stuffed_problem(const Shape& shape, const Fit& fit, const d3::TetMeshF& mesh) {
  d3::StuffedMeshClaims claims;
  claims.distance = [&shape](const Vec3& p) { return shape.signed_distance(p); };
  // S11: cut points and warped vertices lie on the surface; 1e-9 of the
  // finest side allows for the crossing's bisection and the distance's rounding.
  claims.tolerance = 1e-9 * fit.h;
  claims.dihedral = d3::kStuffedDihedralBounds;
  if (auto v = d3::check_stuffed_mesh(mesh.vertices, mesh.tets, claims)) return v->message;
  return std::nullopt;
}

std::optional<std::string> find_feature_problem(const Fit& fit, const d3::TetMeshF& mesh,
                                                const FeatureConformity& conformity) {
  d3::FeatureClaims claims;
  claims.corners = conformity.corners;
  for (const FeatureCurve& piece : conformity.pieces) claims.curves.push_back(piece.points);
  // S32: on the features to 1e-9 h; a chord of a curved crease within h/4.
  claims.tolerance = 1e-9 * fit.h;
  claims.chord = fit.h / 4;
  if (auto v = d3::check_feature_conformity(mesh.vertices, mesh.tets, claims)) return v->message;
  return std::nullopt;
}

Meshed mesh_shape(const Shape& world, const Settings& settings, const Progress& progress) {
  const auto say = [&](const std::string& what) {
    if (progress) progress(what);
  };
  Meshed r;
  if (const SoupReport* soup = world.soup_report()) {
    r.soup = *soup;
    if (settings.strict && soup->flaw_count() > 0)
      throw ShapeError(soup->file + ": " + soup->summary() + " (strict: only a clean closed mesh is meshed)");
  }
  // S24: mesh the shape in local coordinates, map the result back.
  const Normalisation n = normalisation_of(world.bounds());
  const std::unique_ptr<Shape> local = world.normalised(n);
  const Shape& shape = *local;
  StuffOptions options = settings.lattice;
  if (options.size) options.size = std::ldexp(*options.size, -n.exponent);
  const Fit fit = fit_lattice(shape.bounds(), options);
  options.max_level = fit.size.L;
  // S35.7-S35.8 (--crease-cuts): candidate meshes, two held at once.
  const bool crease_cuts = settings.features.on && settings.features.crease_cuts > 0 && settings.impl == Impl::fast;
  // S25: refuse before building what will not fit (a second mesh with S35.8).
  if (const auto limit = settings.memory_limit ? settings.memory_limit : available_memory())
    refuse_what_will_not_fit(shape, options, *limit, crease_cuts ? 2 : 1);
  r.fit = fit;
  r.fit.origin = n.to_world(fit.origin);
  r.fit.scale = std::ldexp(fit.scale, n.exponent);
  r.fit.h = std::ldexp(fit.h, n.exponent);
  say(world.describe() + ": lattice " + std::to_string(fit.size.W) + " x " + std::to_string(fit.size.H) + " x " +
      std::to_string(fit.size.D) + ", max level " + std::to_string(fit.size.L) + ", finest side " + number(r.fit.h));
  // S3-S9 on the fast lattice, or on the reference.
  PhaseTimes times;
  const auto on_lattice = [&](std::size_t leaves, double seconds) {
    r.leaves = leaves;
    say(std::to_string(leaves) + " leaves (" + number(seconds) + " s)");
  };
  // S35.7-S35.8: the features first, the meshes with and without the cut
  // points near them placed on them, each conformed, and the one kept.
  Features features;
  CreaseConformed creased;
  double crease_feature_seconds = 0;
  if (crease_cuts) {
    features = detect_features(shape.surface_triangles(), settings.features.angle);
    creased = stuff_and_conform_on_creases(shape, fit, options, features, settings.features.crease_cuts, fit.h,
                                           settings.features.split_edges, settings.features.split_chords, &times,
                                           &crease_feature_seconds, on_lattice);
    r.stuffed = std::move(creased.stuffed);
    const CreaseCuts& b = creased.all_curves;
    say(std::to_string(b.placed) + " vertices placed on the creases, " + std::to_string(b.excluded) +
        " cut edges kept by the guard, " + std::to_string(b.rounds) + " rounds" + (b.none ? " (none placed)" : "") +
        "; " + std::to_string(creased.candidates) + " candidates, kept " +
        (creased.kept == CreaseCandidate::without      ? "the mesh without placement"
         : creased.kept == CreaseCandidate::all_curves ? "the placement on every curve"
                                                       : "the placement on the curves it gained") +
        " (" + std::to_string(creased.placed_kept) + " vertices placed)");
  } else {
    r.stuffed = stuff_fitted(shape, fit, options, settings.impl, &times, on_lattice);
  }
  r.seconds = {{"lattice", times.lattice},
               {"mesh", times.mesh},
               {"cut", times.cut},
               {"warp", times.warp},
               {"stencils", times.stencils}};
  say(std::to_string(r.stuffed.mesh.tets.size()) + " tetrahedra (" + number(times.total() - times.lattice) + " s)");

  // S21 (a soup whose winding number is below 1/2 at every lattice vertex)
  // or S26 (bad input for this level).
  if (r.stuffed.mesh.tets.empty()) throw ShapeError(empty_mesh_message(world, r.fit));
  // S13a: with a writer, the pass over the tetrahedra runs on its own
  // threads from the moment the mesh is final (here without features, after
  // S29-S35 with them) while the boundary is found and the mesh mapped back
  // and written.
  std::optional<BackgroundStatistics> background;
  const auto start_statistics = [&] {
    if (settings.statistics && settings.write) background.emplace(r.stuffed.mesh, settings.lattice.threads);
  };
  // One grouping of the faces for S11's boundary and M23's regions (the
  // feature snapping below moves vertices only; S35's splits group them again), timed with the statistics.
  const auto t_faces = Clock::now();
  if (!settings.features.on) start_statistics();
  r.regions = io::regions_of(r.stuffed.mesh.tets, &r.boundary);
  const double face_seconds = seconds_since(t_faces);
  // S29-S31: the sharp features of a triangle mesh, and the mesh made to hold them.
  FeatureConformity conformity;
  if (settings.features.on) {
    const auto t0 = Clock::now();
    if (crease_cuts) {  // S35.8 conformed it (the boundary and regions above are of the mesh kept)
      conformity = std::move(creased.conformity);
    } else {
      features = detect_features(shape.surface_triangles(), settings.features.angle);
      conformity = conform_features(r.stuffed.mesh, r.boundary, features, fit.h, settings.features.split_edges,
                                    settings.features.flip, settings.features.split_chords);
      // S35's splits and S35.9's flips changed the tetrahedra: their boundary and regions again.
      if (conformity.splits > 0 || conformity.flips > 0) r.regions = io::regions_of(r.stuffed.mesh.tets, &r.boundary);
    }
    r.features = feature_report(features, conformity);
    r.features->crease_cuts = crease_cuts;
    r.features->placed = creased.all_curves.placed;
    r.features->placed_kept = creased.placed_kept;
    r.seconds.emplace_back("features", crease_feature_seconds + seconds_since(t0));
    start_statistics();
    say(std::to_string(features.edges) + " feature edges, " + std::to_string(features.corners.size()) +
        " corners; conformed " + std::to_string(conformity.corners_conformed) + " corners, " +
        std::to_string(conformity.curves_conformed) + " of " + std::to_string(features.curves.size()) + " curves; " +
        std::to_string(conformity.moves) + " moves, " + std::to_string(conformity.refused) + " refused by the guard, " +
        std::to_string(conformity.splits) + " edges split (" + std::to_string(conformity.chord_splits) + " chords, " +
        std::to_string(conformity.chord_splits_refused) + " chord splits refused), " +
        std::to_string(conformity.splits_undone) + " splits undone");
  }
  const auto t1 = Clock::now();
  // S11 first, so that S27's topology errors below come from meshes that pass it.
  if (settings.check) {
    if (auto why = find_stuffed_problem(shape, fit, r.stuffed.mesh)) throw CheckError(world.describe() + ": " + *why);
    if (settings.features.on)  // S32
      if (auto why = find_feature_problem(fit, r.stuffed.mesh, conformity))
        throw CheckError(world.describe() + ": " + *why);
  }
  // S27: what the mesh is against what the shape is; S26.
  r.topology = topology(r.stuffed.mesh, r.boundary);
  r.warnings = mesh_warnings(world, r.topology, r.fit);
  // A repaired soup's own surface may be non-manifold (overlapping parts
  // meet along curves): there its non-manifold edges are no change, so
  // only a warning even under --check.
  const bool input_manifold = !(r.soup && r.soup->flaw_count() > 0);
  if (settings.check) {
    const auto want = world.surface_components();
    const bool more = want && r.topology.boundary_components > want->count;
    if (more || (r.topology.nonmanifold_edges > 0 && input_manifold))
      throw CheckError(world.describe() + ": " + r.warnings.front());
  }
  if (settings.statistics) {
    if (r.features)  // S33, in world units
      r.features->distance = std::ldexp(feature_distance(r.stuffed.mesh, r.boundary, features, fit.h), n.exponent);
    if (!background)
      r.statistics =
          to_world(statistics(shape, r.stuffed.mesh, r.boundary, settings.hausdorff, settings.lattice.threads), n);
  }
  const auto t_world = Clock::now();
  to_world(r.stuffed.mesh, n, r.fit.h);
  double outside_statistics = seconds_since(t_world);  // the map back and the writing
  double write_seconds = 0;
  if (settings.write) {
    const auto t_write = Clock::now();
    settings.write(r);
    write_seconds = seconds_since(t_write);
    outside_statistics += write_seconds;
  }
  if (background) r.statistics = to_world(background->finish(shape, r.boundary, settings.hausdorff), n);
  // S13a: what the statistics add to the run, the writing's seconds apart.
  r.seconds.emplace_back("statistics", face_seconds + seconds_since(t1) - outside_statistics);
  if (settings.write) r.seconds.emplace_back("write", write_seconds);
  return r;
}

double meshing_seconds(const PhaseSeconds& seconds) {
  double s = 0;
  for (const auto& [phase, t] : seconds)
    if (phase != "statistics" && phase != "write") s += t;
  return s;
}

double total_seconds(const PhaseSeconds& seconds) {
  double s = 0;
  for (const auto& [phase, t] : seconds) s += t;
  return s;
}

void to_world(d3::TetMeshF& mesh, const Normalisation& n, double h) {
  for (Vec3& v : mesh.vertices) {
    v = n.to_world(v);
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
      throw ShapeError("the mesh's coordinates overflow a double (the lattice's margin reaches beyond 1.8e308)");
  }
  // S24: only a translation rounds the map back; what it rounds flat is refused.
  if (!n.translates()) return;
  for (const auto& t : mesh.tets)
    if (orientation(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]) <= 0) {
      const Vec3& p = mesh.vertices[t[0]];
      const double m = std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
      throw ShapeError("a tetrahedron near (" + number(p[0]) + ", " + number(p[1]) + ", " + number(p[2]) +
                       ") is flat once written: coordinates of magnitude " + number(m) + " are spaced " +
                       number(std::nextafter(m, HUGE_VAL) - m) + " apart, too coarse for the finest side " + number(h) +
                       "; use a coarser level or move the shape nearer the origin");
    }
}

}  // namespace bccmis::stuff
