// bccmis::distributed::stuff_on_ranks: the whole run of `bccmis-mpi stuff`
// on every rank as one library call (spec/distributed.md D1-D13), as
// mesh_shape() is for `bccmis stuff`, D16's memory estimate included: the tool parses, writes and prints.
#pragma once

#include <mpi.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/distributed/leaf_piece.h"
#include "bccmis/distributed/replicated.h"
#include "bccmis/io/regions.h"
#include "bccmis/stuff/mesh_shape.h"
#include "bccmis/stuff/stopwatch.h"

namespace bccmis::distributed {

class Forest;

/// What a run is told (D1).
struct RankSettings {
  stuff::StuffOptions lattice;      ///< -L, --min-level, --cells, --size, --threads
  stuff::FeatureSettings features;  ///< on: D12 (needs gather)
  bool check = false;               ///< D12
  bool hausdorff = false;           ///< with statistics: S13's distance on the gathered mesh (D12, D13)
  bool statistics = false;          ///< D11, D13
  bool pieces = false;              ///< a .vtu piece per rank: D7's global ids
  bool gather = false;              ///< the whole mesh on rank 0 (D5)
  /// D16: the memory one rank may take (--memory-limit); unset: MemAvailable
  /// of its node's /proc/meminfo over the ranks sharing that node.
  std::optional<double> memory_limit;
  /// S26's refusal of an empty mesh when set (D14: a frame's, as the serial
  /// animation words it, empty_frame_message); else empty_mesh_message.
  std::optional<std::string> empty_message;
};

/// One rank's result. On rank 0 only: mesh, regions, report, warned.
struct RankRun {
  LeafPiece piece;                                     ///< this rank's (world coordinates unless gathered whole)
  std::vector<std::int64_t> ids;                       ///< D7, with pieces or statistics
  std::vector<std::uint64_t> tetrahedra;               ///< every rank's count
  d3::TetMeshF mesh;                                   ///< with gather: the whole mesh, world coordinates
  io::Regions regions;                                 ///< M23's, of mesh
  std::vector<std::array<std::uint32_t, 3>> boundary;  ///< S11's, of mesh (the .off/.obj outputs)
  stuff::Meshed report;                                ///< with statistics: D11, D13
  bool warned = false;                                 ///< report.warnings holds S27's comparison (D13)
  stuff::PhaseSeconds seconds;                         ///< D11's input, forest, pieces, statistics (from `start`)
  stuff::Clock::time_point since;                      ///< the end of `statistics`: D11's write phase starts here
};

/// D1-D13 on every rank: the fit (S24, S2), D16's memory estimate, the forest (D10), this rank's
/// piece (D3, D4, D6), D7's numbers, the refusal of an empty mesh (S21,
/// S26: ShapeError with empty_mesh_message or `empty_message`), D11's statistics, and with
/// `gather` the pieces gathered on rank 0, the feature step, --check and
/// S27 (D12, D13). Collective over `comm`; after each stage the ranks
/// agree (D6): the lowest failing rank throws its error (ShapeError,
/// CheckError, ...), every other rank RankFailed.
RankRun stuff_on_ranks(const stuff::Shape& world, const RankSettings& s, MPI_Comm comm, stuff::Clock::time_point start);

/// The same run in a lattice fitted by the caller, on `forest` (D10's for
/// lattice.shape; D14, D15: a frame of a moving shape, in_world(), the
/// forest built or moved by the caller, its time `forest` from `start`):
/// D3-D13, `world` the shape `lattice` holds as the messages name it.
/// `lattice` as fitted() or in_world() made it; its lattice is released.
/// The forest's ghost layer may be widened (stuff_own_piece).
RankRun stuff_on_ranks(const stuff::Shape& world, Replicated& lattice, Forest& forest, const RankSettings& s,
                       MPI_Comm comm, stuff::Clock::time_point start);

}  // namespace bccmis::distributed
