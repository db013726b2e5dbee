// bccmis::stuff: closed triangle meshes as shapes (spec/stuffing.md §1),
// through CGAL (AABB tree for distances and crossings, Side_of_triangle_mesh
// with exact predicates for the sign). Only built with CGAL (BCCMIS_WITH_CGAL).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bccmis/io/surface_format.h"
#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/soup_report.h"

namespace bccmis::stuff {

/// The strict path (--strict): reads an OFF, OBJ or STL (ASCII or binary)
/// file in `format`, or the one its extension names (case-insensitive);
/// "-" is standard input ("stdin" in messages), in `format` or the one its
/// content plainly is (io::read_surface). Refuses with ShapeError, naming the file and the
/// problem with its place: a syntax error (file:line:col), an index out of
/// range, a degenerate face, an open mesh (a border edge, by its two vertex
/// indices), a non-manifold edge or vertex, a self-intersection (two faces by
/// index), an empty mesh. A closed mesh oriented inwards is reversed.
std::unique_ptr<Shape> load_surface(const std::string& path, std::optional<io::SurfaceFormat> format = std::nullopt);

/// The same from vertices and triangles in memory (`name` for messages).
std::unique_ptr<Shape> make_mesh_shape(const std::vector<Vec3>& vertices,
                                       const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                       const std::string& name);

/// The default path (spec/stuffing.md S21-S23): reads as load_surface and
/// refuses what it refuses before any check of the surface (the file, the
/// syntax, no faces, a coordinate not finite, an index out of range); a mesh
/// that passes load_surface's checks gives load_surface's shape (with a
/// report of its notes); any other gives the shape of the solid where the
/// winding number of the repaired soup is >= 1/2. Either way
/// Shape::soup_report() says what was found.
std::unique_ptr<Shape> load_soup(const std::string& path, std::optional<io::SurfaceFormat> format = std::nullopt);

/// Whether make_soup_shape dispatches as load_soup does, or makes the soup's
/// shape even of a clean mesh (the tests compare the two on clean meshes).
enum class SoupPath { dispatch, always };

/// load_soup from vertices and triangles in memory.
std::unique_ptr<Shape> make_soup_shape(const std::vector<Vec3>& vertices,
                                       const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                       const std::string& name, SoupPath path = SoupPath::dispatch);

/// The inspection alone (S21, S22): every flaw counted, and the repairs.
/// Refuses as load_soup does before the checks.
SoupReport inspect_soup(const std::vector<Vec3>& vertices, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                        const std::string& name);

/// The largest distance from `points` to the triangle soup (vertices,
/// triangles): one side of a sampled Hausdorff distance.
double max_distance_to_triangles(const std::vector<Vec3>& points, const std::vector<Vec3>& vertices,
                                 const std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace bccmis::stuff
