// fuzz_refine_coarsen: random operation sequences on a small lattice.
//
// Input layout (GEOS/fmt style: every byte string is a valid program):
//   byte 0..2   W = 1 + b0 % 3, H = 1 + b1 % 3, L = b2 % 5
//   then ops    selector byte s, then operands:
//     s & 7 == 0,1,2  refine the k-th live center            (k: 1 byte, 2 if |C| > 256)
//     s & 7 == 3,4    coarsen the k-th node that sits at a refined cell's
//                     center (mostly legal; may be refused)  (k: 1 or 2 bytes)
//     s & 7 == 5      coarsen the k-th node of N (mostly refused)
//     s & 7 == 6      refine at a raw position (x, y)        (2 bytes; mostly refused)
//     s & 7 == 7      coarsen at a raw position (x, y)       (2 bytes; mostly refused)
//     s & 0x80        if the operation was applied, invert it at once
//                     (refine c <-> coarsen c) and compare canonical states
//   At most kMaxOps operations are decoded.
//
// Every decoded operation runs through checked_refine/checked_coarsen (the
// checker before and after, the exact set changes, and a refused operation
// must leave the graph unchanged); applied operations with bit 7 are inverted
// at once and the canonical state must come back byte-identically; at the end
// every refined cell is coarsened, finest level first. The harness is
// fuzz/op_run.h (shared with fuzz_refine_coarsen_3d), the byte program
// tests/testing/byte_program.h. Any failure aborts with the equivalent text
// trace on stderr, so `bccmis replay` reproduces it.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "bccmis/lattice.h"
#include "op_run.h"
#include "testing/byte_program.h"

namespace {

using namespace bccmis;

// The checker runs twice per operation (checked_*), so inputs stay small.
constexpr std::size_t kMaxOps = 96;
constexpr std::string_view kTarget = "fuzz_refine_coarsen";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return 0;
  testing::Bytes in(data, size);
  fuzz::OpRun<Graph, fuzz::Checked2> run(kTarget, testing::decode_lattice(in, 3, 5));
  testing::run_program(
      in, kMaxOps, run.graph(), [&](const Point& c, std::uint8_t s) { run.refine_at(c, (s & 0x80) != 0); },
      [&](const Point& n, std::uint8_t s) { run.coarsen_at(n, (s & 0x80) != 0); }, [](std::uint8_t) {});
  run.coarsen_everything();
  return 0;
}
