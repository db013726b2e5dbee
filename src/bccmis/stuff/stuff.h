// bccmis::stuff: isosurface stuffing on the graded BCC mesh
// (spec/stuffing.md): the lattice fitted to a shape (S2), refined near its
// surface (S3), its graded mesh cut, warped and filled by the stencils
// (S5-S9) into a tetrahedral mesh of the shape.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "bccmis/d3/graph.h"
#include "bccmis/d3/mesh.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/stuff/shape.h"

namespace bccmis::stuff {

/// The parameters of a run (spec/stuffing.md S2, S3, S6).
struct StuffOptions {
  int max_level = 4;            ///< L, the finest level (--max-level)
  int min_level = 0;            ///< every leaf at least this level (--min-level)
  int cells = 4;                ///< N, level-0 cubes along the longest side (--cells)
  std::optional<double> size;   ///< the finest edge length asked for (--size): chooses L
  double alpha_long = 0.24999;  ///< S6
  double alpha_short = 0.41189;
  int threads = 0;  ///< S28-S28c: the threads of S3's tests and the stuffing (--threads); 0: every core
  /// S35.7: when set (the fast stuffer only), asked of every cut point
  /// before S6, in the order of the cut edges, with the edge's ends p, q
  /// (smaller first) and S5's point x: where the cut point goes (x: kept).
  std::function<Vec3(const Vec3& p, const Vec3& q, const Vec3& x)> place_cut;
};

/// Where the lattice sits in space (S2): lattice point p is origin + scale p.
struct Fit {
  d3::LatticeSize size;
  Vec3 origin{};
  double scale = 1;
  double h = 1;  ///< the side of a level-L cube, 2 scale
  Vec3 to_space(const d3::Point& p) const {
    return {origin[0] + scale * static_cast<double>(p.x), origin[1] + scale * static_cast<double>(p.y),
            origin[2] + scale * static_cast<double>(p.z)};
  }
};

/// S2. Throws ShapeError when N 2^L <= 10, the levels are out of range, the
/// initial lattice has 2^31 or more cubes or nodes, or the
/// box is empty or not finite.
Fit fit_lattice(const Bounds& box, const StuffOptions& options);

/// S3's test on one leaf (center c, level l): refine it when l < L and it
/// lies near the surface (|f(c)| <= sqrt(3) r + 4h) or l < --min-level. A
/// function of the leaf alone, so p8est can ask it of a partitioned forest
/// (spec/distributed.md D10).
bool s3_refines(const Shape& shape, const Fit& fit, const StuffOptions& options, const d3::Point& c, int l);

/// S3: the initial lattice of `fit`, refined (through the balance cascade)
/// until no leaf passes the test.
d3::Graph background(const Shape& shape, const Fit& fit, const StuffOptions& options);

/// S3 on the fast lattice: the same refines in the same order, so the same
/// state as background() (d3::canonical_state of its to_graph()).
d3::fast::Lattice background_fast(const Shape& shape, const Fit& fit, const StuffOptions& options);

/// The kind of an output vertex (S11's point data).
enum class StuffVertex : std::uint8_t { lattice = 0, warped = 1, cut = 2 };

/// What stuff() made and counted.
struct Stuffed {
  d3::TetMeshF mesh;  ///< kind: StuffVertex; level: the lattice leaf's level
  std::size_t lattice_tetrahedra = 0, cut_points = 0, warped = 0;
};

/// Seconds spent in each phase of a run: S3 (lattice), the graded mesh
/// (spec/mesh3d.md), S5 with the vertex values (cut), S6 (warp), S7-S9 with
/// the numbering of S8 (stencils).
struct PhaseTimes {
  double lattice = 0, mesh = 0, cut = 0, warp = 0, stencils = 0;
  double total() const { return lattice + mesh + cut + warp + stencils; }
};

/// S5-S9 on the graded mesh of g (a lattice made by background() for the same
/// shape and fit). Throws std::logic_error if a tetrahedron with a cut edge or
/// a warped vertex is not regular (S4) or an output tetrahedron is flat.
/// `times`, when given, receives the mesh, cut, warp and stencils phases.
Stuffed stuff(const Shape& shape, const Fit& fit, const d3::Graph& g, const StuffOptions& options,
              PhaseTimes* times = nullptr);

/// The same on the fast lattice (made by background_fast()): the same mesh
/// as stuff() on the equal d3::Graph, vertex for vertex and tetrahedron for
/// tetrahedron.
Stuffed stuff(const Shape& shape, const Fit& fit, const d3::fast::Lattice& g, const StuffOptions& options,
              PhaseTimes* times = nullptr);

/// The same, freeing g's memory once S5-S6 are done with it (spec/mesh3d.md
/// M26): g is left moved from. The same mesh as the overload above.
Stuffed stuff(const Shape& shape, const Fit& fit, d3::fast::Lattice&& g, const StuffOptions& options,
              PhaseTimes* times = nullptr);

/// S5-S9 on some tetrahedra of the graded mesh of g (S16's incremental
/// stuffing): when `tets` holds every tetrahedron of the whole mesh that has
/// a cut edge, and no tetrahedron left out has a warped vertex, each of them
/// is cut, warped and filled as in the whole mesh. Also reports each output vertex's key (S8: (p, p) for
/// lattice vertex p, the ends in position order for a cut point) and where
/// the output tetrahedra of tets[i] begin (begin[i] .. begin[i + 1]).
struct StuffedPart {
  Stuffed stuffed;
  std::vector<std::array<d3::Point, 2>> keys;
  std::vector<std::uint32_t> begin;
};
StuffedPart stuff_part(const Shape& shape, const Fit& fit, const d3::fast::Lattice& g, const StuffOptions& options,
                       std::span<const d3::Tet> tets);

/// Which lattice a run uses: d3::fast::Lattice (the default) or the reference
/// d3::Graph (--impl reference).
enum class Impl { fast, reference };

/// S3-S9 on a fitted lattice: background (or background_fast) and stuff,
/// the one place that dispatches on `impl`. `times`, when given, receives
/// every phase; `on_lattice`, when given, hears the lattice's leaf count
/// and seconds once it is built.
Stuffed stuff_fitted(const Shape& shape, const Fit& fit, const StuffOptions& options, Impl impl = Impl::fast,
                     PhaseTimes* times = nullptr,
                     const std::function<void(std::size_t leaves, double seconds)>& on_lattice = {});

/// S2-S9 in one call: fit_lattice and stuff_fitted. `times`, when given,
/// receives every phase.
Stuffed stuff_shape(const Shape& shape, const StuffOptions& options, Impl impl = Impl::fast,
                    PhaseTimes* times = nullptr);

/// S12: the sign (-1, 0, 1) of det[b - a, c - a, d - a], exactly.
int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The triangles of exactly one tetrahedron, oriented outward (counter-
/// clockwise seen from outside), for positively oriented tetrahedra.
std::vector<std::array<std::uint32_t, 3>> boundary_triangles(const d3::TetMeshF& mesh);

/// True when a and b hold the same tetrahedra, whatever their numbering:
/// each tetrahedron compared as its level with its four vertices' positions
/// and kinds, sorted (S16's equality with stuff()).
bool same_tetrahedra(const d3::TetMeshF& a, const d3::TetMeshF& b);

/// S10's interval of dihedral angles (degrees): what every stuffed mesh
/// claims, and what S31's guard keeps.
inline constexpr std::array<double, 2> kDihedralBounds{10.7792, 164.8092};

/// What --stats reports of the mesh itself (S13).
struct StuffQuality {
  double volume = 0;
  double min_dihedral = 0, max_dihedral = 0;
  std::size_t below10 = 0;                  ///< tetrahedra with an angle below 10 degrees
  std::array<std::size_t, 13> histogram{};  ///< as d3::MeshQuality::histogram
  std::size_t boundary_triangles = 0;
  bool operator==(const StuffQuality&) const = default;
};
/// On `threads` threads (0: every core); the result is the same on any
/// number (S13a).
StuffQuality quality(const d3::TetMeshF& mesh, int threads = 0);
/// The same when the boundary is already counted (`boundary_triangles`
/// triangles).
StuffQuality quality(const d3::TetMeshF& mesh, std::size_t boundary_triangles, int threads = 0);
/// The same of the tetrahedra `tets` on `vertices`.
StuffQuality quality(const std::vector<Vec3>& vertices, const std::vector<std::array<std::uint32_t, 4>>& tets,
                     std::size_t boundary_triangles, int threads = 0);

/// S13a: the tetrahedra of one chunk of quality()'s pass, whose volumes are
/// summed in order before the chunks' sums are added in chunk order.
inline constexpr std::size_t kQualityChunk = 16384;

}  // namespace bccmis::stuff
