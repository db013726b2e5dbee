// spec/distributed.md D12, D13: the feature step, --check, S27's comparison
// and S13 on the gathered mesh, in mesh_shape()'s order (spec/stuffing.md
// S11, S13, S27, S29-S35, S24), with --crease-cuts S35.8's candidates (D16).
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/distributed/gathered.h"
#include "bccmis/stuff/conform_features.h"
#include "bccmis/stuff/crease_cuts.h"
#include "bccmis/stuff/features.h"
#include "bccmis/stuff/statistics.h"
#include "bccmis/stuff/topology.h"

namespace bccmis::distributed {

Finished finish_gathered(const stuff::Shape& world, const Replicated& r, d3::TetMeshF& mesh,
                         const stuff::FeatureSettings& features, bool check, bool statistics, bool hausdorff) {
  const stuff::Shape& shape = *r.shape;  // S24's local coordinates, as the mesh
  Finished f;
  std::vector<std::array<std::uint32_t, 3>>& boundary = f.boundary;
  f.regions = io::regions_of(mesh.tets, &boundary);
  // S29-S35: the same call, on the same mesh and boundary, as mesh_shape()'s.
  stuff::Features found;
  stuff::FeatureConformity conformity;
  if (features.on && features.crease_cuts > 0) {
    // D16: S35.8 with the gathered mesh as candidate A; B and C made here,
    // on rank 0's whole lattice, by the serial call.
    found = stuff::detect_features(shape.surface_triangles(), features.angle);
    stuff::Stuffed a;
    a.mesh = std::move(mesh);
    stuff::CreaseConformed kept =
        stuff::conform_on_creases(std::move(a), shape, r.fit, r.options, found, features.crease_cuts, r.fit.h,
                                  features.split_edges, features.split_chords);
    mesh = std::move(kept.stuffed.mesh);
    conformity = std::move(kept.conformity);
    f.regions = io::regions_of(mesh.tets, &boundary);
    if (kept.kept != stuff::CreaseCandidate::without) f.cut_points = kept.stuffed.cut_points;
    f.features = stuff::feature_report(found, conformity);
    f.features->crease_cuts = true;
    f.features->placed = kept.all_curves.placed;
    f.features->placed_kept = kept.placed_kept;
  } else if (features.on) {
    found = stuff::detect_features(shape.surface_triangles(), features.angle);
    conformity = stuff::conform_features(mesh, boundary, found, r.fit.h, features.split_edges, features.flip,
                                         features.split_chords);
    if (conformity.splits > 0 || conformity.flips > 0) f.regions = io::regions_of(mesh.tets, &boundary);
    // D13: S33's report, as mesh_shape() fills it.
    f.features = stuff::feature_report(found, conformity);
  }
  // The fit in world units (mesh_shape()'s Meshed::fit), for S26/S27's hints.
  stuff::Fit fit = r.fit;
  fit.origin = r.normalisation.to_world(r.fit.origin);
  fit.scale = std::ldexp(r.fit.scale, r.normalisation.exponent);
  fit.h = std::ldexp(r.fit.h, r.normalisation.exponent);
  // S11 first, then S32, as bccmis stuff --check.
  if (check) {
    if (auto why = stuff::find_stuffed_problem(shape, r.fit, mesh))
      throw stuff::CheckError(world.describe() + ": " + *why);
    if (features.on)
      if (auto why = stuff::find_feature_problem(r.fit, mesh, conformity))
        throw stuff::CheckError(world.describe() + ": " + *why);
  }
  // D13: S27 and S26 on every gathered mesh (a lost component throws).
  f.topology = stuff::topology(mesh, boundary);
  f.warnings = stuff::mesh_warnings(world, f.topology, fit);
  if (check) {
    const stuff::SoupReport* soup = world.soup_report();
    const bool input_manifold = !(soup && soup->flaw_count() > 0);
    const auto want = world.surface_components();
    const bool more = want && f.topology.boundary_components > want->count;
    if (more || (f.topology.nonmanifold_edges > 0 && input_manifold))
      throw stuff::CheckError(world.describe() + ": " + f.warnings.front());
  }
  // D13: S13 (with --hausdorff its sampled distance, as mesh_shape()) and
  // S33 in local coordinates, reported in world units.
  if (statistics) {
    f.statistics = stuff::to_world(stuff::statistics(shape, mesh, boundary, hausdorff), r.normalisation);
    if (f.features)
      f.features->distance =
          std::ldexp(stuff::feature_distance(mesh, boundary, found, r.fit.h), r.normalisation.exponent);
  }
  stuff::to_world(mesh, r.normalisation, fit.h);
  return f;
}

}  // namespace bccmis::distributed
