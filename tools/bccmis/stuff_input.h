// bccmis CLI: what every tool that stuffs reads from its options
// (bccmis stuff, bccmis-mpi stuff): the shape, the output encoding and the
// writers of the tetrahedra.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/io/encoding.h"
#include "bccmis/io/regions.h"
#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/stuff.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

/// Whether `s` ends with `suffix` (an output's extension).
bool ends_with(const std::string& s, std::string_view suffix);

/// The encoding --binary and --compress ask for (spec/cli.md).
io::Encoding encoding(const StuffOptions& o);

/// Stages `mesh` for `path` by its extension: .vtu, .msh, .mesh (the
/// encoding for the first two; `regions`, io::regions_of(mesh.tets), for the
/// last two); any other extension stages nothing.
void add_tetrahedra_output(OutputSet& outputs, const std::string& path, const d3::TetMeshF& mesh,
                           const io::Regions& regions, io::Encoding encoding);

/// Stages every `-o` of `o` for the whole mesh: add_tetrahedra_output, and
/// .off/.obj the boundary `boundary` (S11; --surface-vertices). One rule for
/// bccmis stuff and bccmis-mpi stuff --gather (spec/distributed.md D1).
void add_mesh_outputs(OutputSet& outputs, const StuffOptions& o, const d3::TetMeshF& mesh, const io::Regions& regions,
                      const std::vector<std::array<std::uint32_t, 3>>& boundary);

/// The shape to mesh: --shape NAME or the input mesh (--format, --strict).
/// Throws InputError when both or neither are given, stuff::ShapeError when
/// the shape is refused.
std::shared_ptr<const stuff::Shape> load_shape(const StuffOptions& o);

/// The notices of a repaired triangle-mesh INPUT (spec/cli.md, stuff;
/// spec/stuffing.md S21, S22) as `tool` prints them on standard error: a
/// line naming the flaws found, a line of the vertices welded, each when
/// there are any; empty for a clean file or a built-in shape
/// (spec/distributed.md D1: bccmis-mpi stuff prints the same lines).
std::string soup_notices(const std::string& tool, const stuff::Shape& shape);

/// --path "DX,DY,DZ" (the whole motion of --animate, spec/stuffing.md
/// S14), or the library's default path for `shape` when `text` is empty.
/// Throws InputError naming the item that is not a number.
stuff::Vec3 parse_path(const std::string& text, const stuff::Shape& shape);

/// STEM_NNNN plus `extension`: a frame of --animate (k), a rank's piece
/// (spec/distributed.md D1, D14).
std::string numbered(const std::string& stem, int k, std::string_view extension);

/// The lattice's options (-L, --min-level, --cells, --size, --threads) as
/// the library takes them, for bccmis stuff and bccmis-mpi stuff alike.
stuff::StuffOptions lattice_options(const StuffOptions& o);

}  // namespace bccmis::cli
