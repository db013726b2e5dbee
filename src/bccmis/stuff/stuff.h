// bccmis::stuff: isosurface stuffing on the graded BCC mesh
// (spec/stuffing.md): the lattice fitted to a shape (S2), refined near its
// surface (S3), its graded mesh cut, warped and filled by the stencils
// (S5-S9) into a tetrahedral mesh of the shape.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "bccmis/d3/graph.h"
#include "bccmis/d3/mesh.h"
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
};

/// Where the lattice sits in space (S2): lattice point p is origin + scale p.
struct Fit {
  d3::LatticeSize3 size;
  Vec3 origin{};
  double scale = 1;
  double h = 1;  ///< the side of a level-L cube, 2 scale
  Vec3 to_space(const d3::Point3& p) const {
    return {origin[0] + scale * static_cast<double>(p.x), origin[1] + scale * static_cast<double>(p.y),
            origin[2] + scale * static_cast<double>(p.z)};
  }
};

/// S2. Throws ShapeError when N 2^L <= 10, the levels are out of range or the
/// box is empty or not finite.
Fit fit_lattice(const Bounds& box, const StuffOptions& options);

/// S3: the initial lattice of `fit`, refined (through the balance cascade)
/// until no leaf passes the test.
d3::Graph3 background(const Shape& shape, const Fit& fit, const StuffOptions& options);

/// The kind of an output vertex (S11's point data).
enum class StuffVertex : std::uint8_t { lattice = 0, warped = 1, cut = 2 };

/// What stuff() made and counted.
struct Stuffed {
  d3::TetMeshF mesh;  ///< kind: StuffVertex; level: the lattice leaf's level
  std::size_t lattice_tetrahedra = 0, cut_points = 0, warped = 0;
};

/// S5-S9 on the graded mesh of g (a lattice made by background() for the same
/// shape and fit). Throws std::logic_error if a tetrahedron with a cut edge or
/// a warped vertex is not regular (S4) or an output tetrahedron is flat.
Stuffed stuff(const Shape& shape, const Fit& fit, const d3::Graph3& g, const StuffOptions& options);

/// S12: the sign (-1, 0, 1) of det[b - a, c - a, d - a], exactly.
int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The triangles of exactly one tetrahedron, oriented outward (counter-
/// clockwise seen from outside), for positively oriented tetrahedra.
std::vector<std::array<std::uint32_t, 3>> boundary_triangles(const d3::TetMeshF& mesh);

/// What --stats reports of the mesh itself (S13).
struct StuffQuality {
  double volume = 0;
  double min_dihedral = 0, max_dihedral = 0;
  std::size_t below10 = 0;                  ///< tetrahedra with an angle below 10 degrees
  std::array<std::size_t, 13> histogram{};  ///< as d3::MeshQuality::histogram
  std::size_t boundary_triangles = 0;
};
StuffQuality quality(const d3::TetMeshF& mesh);

/// The boundary surface as OFF or OBJ (S11): the vertices it uses, the triangles.
void write_off(std::ostream& out, const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& tris);
void write_obj(std::ostream& out, const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& tris);

}  // namespace bccmis::stuff
