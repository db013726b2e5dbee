// bccmis::stuff::SoupReport: what the inspection of a triangle-mesh file
// found and what was repaired (spec/stuffing.md, "Triangle soups", S20-S23).
// Carried by the shape (Shape::soup_report) and by mesh_shape's result
// (Meshed::soup); printed by `bccmis stuff`.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace bccmis::stuff {

/// One kind of flaw: how many, and the first few (by their smallest face)
/// as the input's face numbers involved, ascending.
struct SoupFlaw {
  std::size_t count = 0;
  std::vector<std::vector<std::size_t>> first;
};

struct SoupReport {
  /// How many instances of each kind are listed.
  static constexpr std::size_t kListed = 5;

  /// The flaws (S21), each a reason for --strict to refuse; counted in the
  /// unit named: a face, a pair of faces, an edge (its faces listed), a vertex
  /// (the faces of two of its fans listed).
  enum Kind : std::size_t {
    degenerate_faces,    ///< a repeated vertex or zero area (one face)
    duplicate_faces,     ///< the same three vertices the same way round as an earlier face (kept, dropped)
    back_to_back_faces,  ///< a pair on the same three vertices the opposite way round
    nonmanifold_edges,   ///< an edge of more than two faces
    border_edges,        ///< an edge of one face (a hole's rim)
    inconsistent_edges,  ///< an edge whose two faces run along it the same way
    nonmanifold_vertices,
    self_intersections,  ///< a pair of faces that meet other than in a shared vertex or edge
    kKinds
  };
  /// "degenerate_faces", ...: the names in --json and --stats.
  static const char* key(Kind k);

  std::string file;       ///< as given, for messages
  std::size_t faces = 0;  ///< the input's triangles (after fanning)
  std::array<SoupFlaw, kKinds> flaws;

  // What was found that is no flaw, and the repairs (S22).
  std::size_t components = 0;         ///< edge-connected components of the repaired soup
  std::size_t inward_components = 0;  ///< components reversed to bound positive volume (S22)
  std::size_t flipped_faces = 0;      ///< faces turned to agree with their component's neighbours
  std::size_t dropped_faces = 0;      ///< degenerate, duplicate and back-to-back faces left out
  std::size_t welded_vertices = 0;    ///< used vertices with the coordinates of an earlier one, merged into it
  SoupFlaw bad_normals;               ///< STL facet normals not finite, not numbers or against the vertex order

  /// The total count of flaws; 0 when the file passed the strict checks.
  std::size_t flaw_count() const;
  /// "3 self-intersecting face pairs, 2 border edges" (the kinds found, in
  /// Kind order); empty when none.
  std::string summary() const;
};

}  // namespace bccmis::stuff
