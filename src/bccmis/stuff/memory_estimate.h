// bccmis::stuff::memory_estimate: what a run will need, estimated from the
// fitted lattice before it is built (spec/stuffing.md S25), and the memory
// the machine has for it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

/// S25: the bytes a run's peak holds per leaf of the probe's estimate, about
/// what was measured on the sphere (1.79 KB at level 5, 1.84 KB at level 7).
inline constexpr double kBytesPerLeaf = 1900;

/// S25: the bytes of a second stuffed mesh per estimated leaf, which S35.8
/// (--crease-cuts) holds beside the first: its tetrahedra, vertices and
/// boundary on the sphere at level 5 (80.1 MB) over the probe's 194,000
/// estimated leaves, rounded up.
inline constexpr double kSecondMeshBytesPerLeaf = 420;

/// S25: an estimate of the leaves S3 makes for `shape` at options.max_level
/// (the shape in S24's local coordinates, as the run sees it): every cube of
/// the lattice when that is affordable, else a probe lattice at a coarse
/// level P whose leaves grow by 4 a level, as a surface's do. `meshes`: the
/// stuffed meshes the run holds at once, 2 with S35.8's candidates.
struct MemoryEstimate {
  double leaves = 0;
  int meshes = 1;
  double bytes_per_leaf() const { return kBytesPerLeaf + (meshes - 1) * kSecondMeshBytesPerLeaf; }
  double bytes() const { return leaves * bytes_per_leaf(); }
};
MemoryEstimate estimate_memory(const Shape& shape, const StuffOptions& options, double available_bytes, int meshes = 1);

/// S25's refusal: "max level L needs about LEAVES leaves, BYTES GB WHOSE
/// (HOW), more than the AVAILABLE GB of memory available[ FOR]; -L N would
/// fit", N the finest level whose estimate (falling by 4 a level) fits, not
/// below `coarsest`; when none from `coarsest` up fits: "; even -L C, the
/// coarsest max level these options allow, would not fit" (S25).
/// `whose` is "by S25's estimate" for one process; bccmis-mpi stuff names
/// the rank (spec/distributed.md D16).
std::string too_much_memory(int level, double leaves, double bytes, double available_bytes, const std::string& whose,
                            const std::string& how, const std::string& for_whom, int coarsest);

/// S25: the coarsest max level `options` allow: at least --min-level, and
/// the least L with --cells x 2^L > 10 (S2).
int coarsest_max_level(const StuffOptions& options);

/// MemAvailable of /proc/meminfo in bytes, or nothing when it cannot be read.
std::optional<double> available_memory();

/// S25: throws ShapeError, with the estimate and the finest level that would
/// fit, when the estimate for `options` (and `meshes` meshes at once)
/// exceeds `available_bytes`; an estimate equal to it fits.
void refuse_what_will_not_fit(const Shape& shape, const StuffOptions& options, double available_bytes, int meshes = 1);

}  // namespace bccmis::stuff
