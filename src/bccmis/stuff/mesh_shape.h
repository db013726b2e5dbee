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

#include "bccmis/io/regions.h"
#include "bccmis/io/surface_format.h"
#include "bccmis/stuff/conform_features.h"
#include "bccmis/stuff/features.h"
#include "bccmis/stuff/normalisation.h"
#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/soup_report.h"
#include "bccmis/stuff/statistics.h"
#include "bccmis/stuff/stopwatch.h"
#include "bccmis/stuff/stuff.h"
#include "bccmis/stuff/topology.h"

namespace bccmis::stuff {

/// S29-S33: whether a run keeps the sharp features of a triangle-mesh
/// shape, and the feature angle.
struct FeatureSettings {
  bool on = false;
  double angle = kDefaultFeatureAngle;  ///< phi, degrees (S29)
  bool split_edges = true;              ///< S35's splits; false: S30-S34 only
  bool flip = true;                     ///< S35.9's flips at a refused move; false: none
  bool split_chords = true;             ///< S35.11's chord splits (with split_edges); false: none
  double crease_cuts = 0;               ///< S35.7's delta (of h), kept as S35.8 says; 0: none
};

struct Meshed;

/// Everything a run is told.
struct Settings {
  StuffOptions lattice;     ///< S2, S3, S6: levels, cells, size, the alphas
  Impl impl = Impl::fast;   ///< the fast lattice, or the reference (its oracle)
  bool statistics = false;  ///< compute S13's statistics (counts, volume, angles)
  bool hausdorff = false;   ///< with statistics, also S13's sampled Hausdorff distance
  bool check = false;       ///< run the checker's stuffed-mesh layer on the result
  /// Refuse a triangle mesh with any flaw (S21): a shape whose soup report
  /// counts flaws is refused with the first one's message, as
  /// load_mesh_file(path, true) refuses it when reading.
  bool strict = false;
  /// The memory a run may take (S25); unset: MemAvailable of /proc/meminfo.
  std::optional<double> memory_limit;
  FeatureSettings features;  ///< S29-S33; off: the mesh of S5-S9 exactly
  /// When set, called once with the result in world coordinates (the mesh,
  /// its boundary and regions; not yet its statistics) while the statistics
  /// are computed on other threads (S13a): the caller's writing of the
  /// outputs, timed as the phase "write".
  std::function<void(const Meshed&)> write;
};

/// One line of news for a person watching ("12,345 leaves (0.5 s)").
using Progress = std::function<void(std::string_view)>;

/// Seconds per phase, in the order they ran (S13's names: lattice, mesh,
/// cut, warp, stencils, statistics).
using PhaseSeconds = std::vector<std::pair<std::string, double>>;

/// S13's sums of a run's phases: `meshing`, every phase but "statistics"
/// and "write" (what the comparison with other meshers times), and `total`.
double meshing_seconds(const PhaseSeconds& seconds);
double total_seconds(const PhaseSeconds& seconds);

/// What a run made.
struct Meshed {
  Fit fit;                                             ///< where the lattice sat (S2); fit.size.L is the level used
  std::size_t leaves = 0;                              ///< the background lattice's leaves (S3)
  Stuffed stuffed;                                     ///< the mesh and its counts (S5-S9)
  std::vector<std::array<std::uint32_t, 3>> boundary;  ///< S11, outward
  io::Regions regions;  ///< the components and the boundary by component (mesh3d.md M23), for the FEM writers
  std::optional<Statistics> statistics;   ///< with Settings::statistics
  std::optional<SoupReport> soup;         ///< the shape's soup report (S21), when it has one
  MeshTopology topology;                  ///< S27: the boundary's components, Euler characteristic
  std::vector<std::string> warnings;      ///< S27: a changed topology, one line each
  std::optional<FeatureReport> features;  ///< S33, with Settings::features
  PhaseSeconds seconds;
  /// The counts of statistics_counts() this run could not compute, printed
  /// as "-" and null (bccmis-mpi stuff: `warped`, spec/distributed.md D11).
  std::vector<std::string> not_computed;
};

/// A check of the result failed (Settings::check): the message names the
/// shape and what is wrong.
class CheckError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// S2-S13 on `shape`, in the local coordinates of S24 (the mesh, the fit and
/// the statistics reported in the shape's own). Throws ShapeError when the lattice cannot be fitted
/// (S2's refusals), when a soup's mesh has no tetrahedron ("<file>: encloses
/// no volume ...", S21) or, with Settings::strict, when the shape's soup
/// report has flaws, when the coordinates cannot hold the result (S24), the
/// run will not fit the memory (S25), the mesh is empty (S26) or lost a
/// component of the surface (S27); CheckError when Settings::check finds a
/// problem or a warning of S27.
Meshed mesh_shape(const Shape& shape, const Settings& settings, const Progress& progress = {});

/// S24's map back: every vertex of `mesh` (made in n's local coordinates)
/// to world coordinates. Throws ShapeError when a coordinate overflows or,
/// when n translates, a tetrahedron is no longer positively oriented once
/// rounded (`h`, the finest side in world units, for the message).
void to_world(d3::TetMeshF& mesh, const Normalisation& n, double h);

/// S26's hint: "bad input for this level (the finest cell side of `fit`
/// against the thinnest extent of `box`, both in world units); -L N would
/// resolve it", N the first level whose finest side is at most a quarter of it.
std::string level_hint(const Bounds& box, const Fit& fit);

/// S27's and S26's warnings of a mesh of `world` whose boundary has the
/// topology `t`, made on `fit` (world units), in order: more boundary
/// components than the shape's surface has, non-manifold edges, a mesh
/// coarser than a quarter of the shape's thinnest extent. Throws ShapeError
/// when the boundary has fewer components than the surface (S27: "a
/// component is lost"). One rule for `bccmis stuff` and `bccmis-mpi stuff
/// --stats` (spec/distributed.md D11).
std::vector<std::string> mesh_warnings(const Shape& world, const MeshTopology& t, const Fit& fit);

/// Why a mesh of `shape` without tetrahedra is refused, `fit` in world
/// units: a soup with flaws encloses no volume (S21: "<file>: encloses no
/// volume (the winding number is below 1/2 at every lattice vertex)"), any
/// other shape is bad input for this level (S26: "<shape>: the mesh is
/// empty: " and level_hint). One message for `bccmis stuff` and every rank
/// count of `bccmis-mpi stuff`.
std::string empty_mesh_message(const Shape& shape, const Fit& fit);

/// The checker's feature layer (bccmis/invariants/d3/feature_conformity.h)
/// on a mesh of the lattice `fit` and what S30 conformed in it: a vertex at
/// each corner within 1e-9 h, each piece covered (S32). The message of the
/// first problem, or empty.
std::optional<std::string> find_feature_problem(const Fit& fit, const d3::TetMeshF& mesh,
                                                const FeatureConformity& conformity);

/// The shape a user names: a triangle mesh file (.off, .obj, .stl), read
/// through CGAL (ShapeError naming the file when this build has no CGAL or
/// the file is refused). By default any soup that parses and has a face
/// (load_soup, S21-S23; the shape's soup_report() says what was found and
/// repaired); with `strict` only a clean closed mesh, refused at its first
/// flaw (load_surface, §1's checks). `format` overrides the extension; "-"
/// is standard input, in `format` or as its content says.
std::unique_ptr<Shape> load_mesh_file(const std::string& path, bool strict = false,
                                      std::optional<io::SurfaceFormat> format = std::nullopt);

/// The checker's stuffed-mesh layer (bccmis/invariants/d3/stuffed_mesh.h) on
/// a mesh of `shape` on the lattice `fit`: boundary vertices within 1e-9 h
/// of the surface, every dihedral angle in S10's interval. The message of
/// the first problem, or empty.
std::optional<std::string> find_stuffed_problem(const Shape& shape, const Fit& fit, const d3::TetMeshF& mesh);

}  // namespace bccmis::stuff
