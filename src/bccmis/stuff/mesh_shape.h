// bccmis::stuff::mesh_shape: the stuffing library's one entry point. A shape
// and typed settings in; the tetrahedral mesh, its boundary, the statistics
// of S13 and the seconds of each phase out (spec/stuffing.md S2-S13).
//
//   auto shape = bccmis::stuff::make_builtin("torus:R=1,r=0.4");
//   bccmis::stuff::Settings s;
//   s.lattice.max_level = 4;
//   s.statistics = true;
//   const auto r = bccmis::stuff::mesh_shape(*shape, s);
//   // r.stuffed.mesh: vertices, tets, kind, level; r.statistics->min_dihedral ...
//
// `bccmis stuff` is this call and the writers; `bccmis stuff --animate` is
// animate_shape() (animate_shape.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/statistics.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

/// Everything a run is told.
struct Settings {
  StuffOptions lattice;     ///< S2, S3, S6: levels, cells, size, the alphas
  Impl impl = Impl::fast;   ///< the fast lattice, or the reference (its oracle)
  bool statistics = false;  ///< compute S13's statistics (quality, Hausdorff)
  bool check = false;       ///< run the checker's stuffed-mesh layer on the result
};

/// One line of news for a person watching ("12,345 leaves (0.5 s)").
using Progress = std::function<void(std::string_view)>;

/// Seconds per phase, in the order they ran (S13's names: lattice, mesh,
/// cut, warp, stencils, statistics).
using PhaseSeconds = std::vector<std::pair<std::string, double>>;

/// What a run made.
struct Meshed {
  Fit fit;                                             ///< where the lattice sat (S2); fit.size.L is the level used
  std::size_t leaves = 0;                              ///< the background lattice's leaves (S3)
  Stuffed stuffed;                                     ///< the mesh and its counts (S5-S9)
  std::vector<std::array<std::uint32_t, 3>> boundary;  ///< S11, outward
  std::optional<Statistics> statistics;                ///< with Settings::statistics
  PhaseSeconds seconds;
};

/// A check of the result failed (Settings::check): the message names the
/// shape and what is wrong.
class CheckError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// S2-S13 on `shape`. Throws ShapeError when the lattice cannot be fitted
/// (S2's refusals), CheckError when Settings::check finds a problem.
Meshed mesh_shape(const Shape& shape, const Settings& settings, const Progress& progress = {});

/// The shape a user names: a triangle mesh file (.off, .obj, .stl), read
/// through CGAL (ShapeError naming the file when this build has no CGAL or
/// the file is refused).
std::unique_ptr<Shape> load_mesh_file(const std::string& path);

/// The checker's stuffed-mesh layer (bccmis/invariants/d3/stuffed_mesh.h) on
/// a mesh of `shape` on the lattice `fit`: boundary vertices within 1e-9 h
/// of the surface, every dihedral angle in S10's interval. The message of
/// the first problem, or empty.
std::optional<std::string> find_stuffed_problem(const Shape& shape, const Fit& fit, const d3::TetMeshF& mesh);

}  // namespace bccmis::stuff
