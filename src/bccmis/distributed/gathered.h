// bccmis::distributed::finish_gathered: the serial run's steps after S9 that
// read the whole mesh (the features, S29-S35, --check's layers, S27's
// comparison and, with --stats, S13), on the mesh gathered on one rank
// (spec/distributed.md D12, D13).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/distributed/replicated.h"
#include "bccmis/io/regions.h"
#include "bccmis/stuff/mesh_shape.h"

namespace bccmis::distributed {

/// D13: what finish_gathered found, as mesh_shape() reports it.
struct Finished {
  io::Regions regions;                                 ///< M23's, for the writers
  std::vector<std::array<std::uint32_t, 3>> boundary;  ///< S11, outward (after S35's splits): .off, .obj
  stuff::MeshTopology topology;                        ///< S27, of the boundary after S35's splits
  std::vector<std::string> warnings;                   ///< S26, S27 (mesh_warnings)
  std::optional<stuff::FeatureReport> features;        ///< S33, with the features on
  std::optional<stuff::Statistics> statistics;         ///< S13 in world units, when asked
  /// S6's cut points of the candidate S35.8 kept when it is B or C (made on
  /// rank 0's whole lattice, D16); unset for A (D11's count stands).
  std::optional<std::size_t> cut_points;
};

/// D12: mesh_shape()'s steps after S9, in its order, on `mesh`, the whole
/// mesh gathered (gather_pieces) from pieces kept in S24's local
/// coordinates: S11's boundary and M23's regions; with `features.on`, S29 on
/// the shape's triangles and S30-S35 (conform_features), the regions again
/// after a split (with `features.crease_cuts`, S35.8's candidates, the
/// gathered mesh as A, B and C stuffed (S3-S9) as the serial run stuffs them, D16); with `check`, the checker's
/// stuffed-mesh layer and the feature layer (S32); S27's topology and the warnings (D13); with `check`, S27's extra
/// components or non-manifold edges refused; with `statistics`, S13 (its sampled Hausdorff distance with `hausdorff`)
/// and S33's feature distance (D13); then S24's map to world coordinates. `world` is the shape as read, `r` as fitted()
/// made it. Throws stuff::CheckError on a problem the checks find (S11, S32, S27's extra components or non-manifold
/// edges), stuff::ShapeError on S27's lost component or S24's overflow, with mesh_shape()'s messages.
Finished finish_gathered(const stuff::Shape& world, const Replicated& r, d3::TetMeshF& mesh,
                         const stuff::FeatureSettings& features, bool check, bool statistics = false,
                         bool hausdorff = false);

}  // namespace bccmis::distributed
