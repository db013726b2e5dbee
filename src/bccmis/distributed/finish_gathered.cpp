// spec/distributed.md D12: the feature step and --check on the gathered
// mesh, in mesh_shape()'s order (spec/stuffing.md S11, S27, S29-S35, S24).
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "bccmis/distributed/gathered.h"
#include "bccmis/stuff/conform_features.h"
#include "bccmis/stuff/features.h"
#include "bccmis/stuff/topology.h"

namespace bccmis::distributed {

io::Regions finish_gathered(const stuff::Shape& world, const Replicated& r, d3::TetMeshF& mesh,
                            const stuff::FeatureSettings& features, bool check) {
  const stuff::Shape& shape = *r.shape;  // S24's local coordinates, as the mesh
  std::vector<std::array<std::uint32_t, 3>> boundary;
  io::Regions regions = io::regions_of(mesh.tets, &boundary);
  // S29-S35: the same call, on the same mesh and boundary, as mesh_shape()'s.
  stuff::FeatureConformity conformity;
  if (features.on) {
    const stuff::Features found = stuff::detect_features(shape.surface_triangles(), features.angle);
    conformity = stuff::conform_features(mesh, boundary, found, r.fit.h, features.split_edges);
    if (conformity.splits > 0) regions = io::regions_of(mesh.tets, &boundary);
  }
  // The fit in world units (mesh_shape()'s Meshed::fit), for S26/S27's hints.
  stuff::Fit fit = r.fit;
  fit.origin = r.normalisation.to_world(r.fit.origin);
  fit.scale = std::ldexp(r.fit.scale, r.normalisation.exponent);
  fit.h = std::ldexp(r.fit.h, r.normalisation.exponent);
  if (check) {
    // S11 first, then S32, then S27, as bccmis stuff --check.
    if (auto why = stuff::find_stuffed_problem(shape, r.fit, mesh))
      throw stuff::CheckError(world.describe() + ": " + *why);
    if (features.on)
      if (auto why = stuff::find_feature_problem(r.fit, mesh, conformity))
        throw stuff::CheckError(world.describe() + ": " + *why);
    const stuff::MeshTopology t = stuff::topology(mesh, boundary);
    const std::vector<std::string> warnings = stuff::mesh_warnings(world, t, fit);  // a lost component throws
    const stuff::SoupReport* soup = world.soup_report();
    const bool input_manifold = !(soup && soup->flaw_count() > 0);
    const auto want = world.surface_components();
    const bool more = want && t.boundary_components > want->count;
    if (more || (t.nonmanifold_edges > 0 && input_manifold))
      throw stuff::CheckError(world.describe() + ": " + warnings.front());
  }
  stuff::to_world(mesh, r.normalisation, fit.h);
  return regions;
}

}  // namespace bccmis::distributed
