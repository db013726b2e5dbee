// bccmis::stuff::BackgroundStatistics: S13's pass over the tetrahedra
// (quality()) on its own threads while the caller goes on (spec/stuffing.md
// S13a): it finds the boundary, takes the mesh to world coordinates and
// writes it meanwhile, and finish() joins the pass and completes S13.
//
//   BackgroundStatistics pass(mesh, threads);   // once the mesh is final
//   ... boundary, to_world(mesh), writing ...  // only the vertices change
//   const Statistics s = pass.finish(shape, boundary, hausdorff);
#pragma once

#include <array>
#include <cstdint>
#include <exception>
#include <thread>
#include <vector>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/statistics.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

class BackgroundStatistics {
 public:
  /// Starts quality() of `mesh` on `threads` threads (0: every core) over a
  /// copy of its vertices: the caller may change the mesh's vertices, not
  /// its tetrahedra, until finish() or the destructor, which joins.
  BackgroundStatistics(const d3::TetMeshF& mesh, int threads);
  BackgroundStatistics(const BackgroundStatistics&) = delete;
  BackgroundStatistics& operator=(const BackgroundStatistics&) = delete;

  /// Joins the pass and returns statistics() of the mesh as it was when
  /// the pass started, with `boundary` (S11) and, when asked, the sampled
  /// Hausdorff distance to `shape`. Rethrows the pass's error.
  Statistics finish(const Shape& shape, const std::vector<std::array<std::uint32_t, 3>>& boundary, bool hausdorff);

 private:
  std::vector<Vec3> vertices_;  ///< the mesh's vertices when the pass started
  const std::vector<std::array<std::uint32_t, 4>>& tets_;
  StuffQuality quality_;
  std::exception_ptr error_;
  std::jthread thread_;  ///< last: joined before the members it reads are destroyed
};

}  // namespace bccmis::stuff
