// bccmis::distributed::finish_gathered: the serial run's steps after S9 that
// read the whole mesh (the features, S29-S35, and --check's layers), on the
// mesh gathered on one rank (spec/distributed.md D12).
#pragma once

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/distributed/replicated.h"
#include "bccmis/io/regions.h"
#include "bccmis/stuff/mesh_shape.h"

namespace bccmis::distributed {

/// D12: mesh_shape()'s steps after S9, in its order, on `mesh`, the whole
/// mesh gathered (gather_pieces) from pieces kept in S24's local
/// coordinates: S11's boundary and M23's regions; with `features.on`, S29 on
/// the shape's triangles and S30-S35 (conform_features), the regions again
/// after a split; with `check`, the checker's stuffed-mesh layer, the
/// feature layer (S32) and S27's topology as `bccmis stuff --check` runs
/// them; then S24's map to world coordinates. `world` is the shape as read,
/// `r` as fitted() made it. Returns the regions, for the writers. Throws
/// stuff::CheckError on a problem the checks find (S11, S32, S27's extra
/// components or non-manifold edges), stuff::ShapeError on S27's lost
/// component or S24's overflow, with mesh_shape()'s messages.
io::Regions finish_gathered(const stuff::Shape& world, const Replicated& r, d3::TetMeshF& mesh,
                            const stuff::FeatureSettings& features, bool check);

}  // namespace bccmis::distributed
