// fuzz_refine_coarsen_3d: random operation sequences on a small 3D lattice
// (spec/lattice3d.md), the 3D counterpart of fuzz_refine_coarsen.
//
// Input layout (every byte string is a valid program; the byte program of
// tests/testing/byte_program.h, decoded against d3::Graph):
//   byte 0..3   W = 1 + b0 % 3, H = 1 + b1 % 3, D = 1 + b2 % 3, L = b3 % 5
//   then ops    selector byte s, then operands:
//     s & 7 == 0,1,2  refine the k-th live center            (k: 1 byte, 2 if |C| > 256)
//     s & 7 == 3,4    coarsen the k-th node that sits at a refined cell's
//                     center (mostly legal; may be refused)  (k: 1 or 2 bytes)
//     s & 7 == 5      coarsen the k-th node of N (mostly refused)
//     s & 7 == 6      refine at a raw position (x, y, z)     (3 bytes; mostly refused;
//                     0xff = INT64_MAX, 0xfe = INT64_MIN)
//     s & 7 == 7      coarsen at a raw position (x, y, z)    (3 bytes; mostly refused)
//     s & 0x80        if the operation was applied, invert it at once
//                     (refine c <-> coarsen c) and compare canonical states
//   At most kMaxOps operations are decoded; a refine that could take the
//   lattice past kMaxCells cells is skipped.
//
// Every decoded operation runs through d3::Checked (fuzz/d3/checked.h): the 3D
// checker's layers 1-4 after every applied operation, the mesh layer
// (check_mesh on tetrahedra(g)) after every applied operation on lattices of
// at most 16 cells and every 64th applied operation beyond, the exact changes of C and N, and a refusal
// must leave the canonical state byte-identical. Applied operations with bit
// 7 are inverted at once and the canonical state must come back
// byte-identically. After the program, all five layers run once more; then
// every refined cell is coarsened, finest level first, and the lattice must
// be the initial one. The harness is fuzz/op_run.h (shared with
// fuzz_refine_coarsen). Any failure aborts with the equivalent 3D text trace
// on stderr, so `bccmis replay` reproduces it.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "bccmis/d3/lattice.h"
#include "d3/checked.h"
#include "op_run.h"
#include "testing/byte_program.h"

namespace {

using namespace bccmis;

constexpr std::size_t kMaxOps = 96;
constexpr std::size_t kMaxCells = 400;
// The mesh layer (exact orientations and volumes through GMP; about 0.1 s a
// call under the sanitizers) costs far more than layers 1-4: it runs after
// every applied operation up to kMeshCells cells, after every kMeshEvery-th
// applied operation beyond, and at the end of the program.
constexpr std::size_t kMeshCells = 16;
constexpr std::size_t kMeshEvery = 64;

d3::fuzz::Checked checked() {
  d3::fuzz::Checked c;
  c.mesh_cells = kMeshCells;
  c.mesh_every = kMeshEvery;
  return c;
}
constexpr std::string_view kTarget = "fuzz_refine_coarsen_3d";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  testing::Bytes in(data, size);
  fuzz::OpRun<d3::Graph, d3::fuzz::Checked> run(kTarget, testing::decode_lattice<d3::LatticeSize>(in, 3, 5), checked(),
                                                kMaxCells);
  testing::run_program(
      in, kMaxOps, run.graph(), [&](const d3::Point& c, std::uint8_t s) { run.refine_at(c, (s & 0x80) != 0); },
      [&](const d3::Point& n, std::uint8_t s) { run.coarsen_at(n, (s & 0x80) != 0); }, [](std::uint8_t) {});
  run.check([&](const d3::Graph& g) {
    if (auto p = d3::fuzz::problem(g, true)) run.fail("at the end of the program: " + *p);
  });
  run.coarsen_everything();
  return 0;
}
