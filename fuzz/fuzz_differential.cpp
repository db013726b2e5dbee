// fuzz_differential: the reference core and bccmis::fast::Lattice driven by
// the same operations; every observable must agree (issue 9).
//
// Input layout (every byte string is a valid program):
//   byte 0..2   W = 1 + b0 % 4, H = 1 + b1 % 4, L = b2 % 6
//   then ops    selector byte s, then operands:
//     s & 7 == 0,1,2  refine the k-th live center of the reference  (k: 1 byte, 2 if |C| > 256)
//     s & 7 == 3,4    coarsen the k-th node at a refined cell's center (mostly legal)
//     s & 7 == 5      coarsen the k-th node of N (mostly refused)
//     s & 7 == 6      refine at a raw position (x, y)                (2 bytes; mostly refused)
//     s & 7 == 7      coarsen at a raw position (x, y)               (2 bytes; mostly refused)
//     s & 0x40        afterwards, the fast side goes on with a copy of itself
//                     (s & 0x20 clear) or with Lattice::from_graph of the
//                     reference state (s & 0x20 set)
//     s & 0x80        the operation goes through refine_each / coarsen_each
//   At most kMaxOps operations are decoded.
//
// After every operation: can_refine and can_coarsen at the position (both
// operations, before it ran), the decision, Y and J+/J-, the counts, the
// canonical state byte for byte, and the fast lattice's own audit. At the end:
// neighbors, is_center, is_node and level_of at every vertex and at the positions
// around the domain. Any difference aborts with the equivalent text trace on
// stderr, so `bccmis replay` (reference) reproduces the run. The lock-step
// comparison is tests/testing/twin.h, the byte program
// tests/testing/byte_program.h.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "bccmis/io/format.h"
#include "fuzz_util.h"
#include "testing/byte_program.h"
#include "testing/twin.h"

namespace {

using namespace bccmis;

constexpr std::size_t kMaxOps = 128;
constexpr std::string_view kTarget = "fuzz_differential";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return 0;
  testing::Bytes in(data, size);
  testing::Twin twin(testing::decode_lattice(in, 4, 6),
                     [](const std::string& what, const Trace& so_far) { fuzz::fail(kTarget, what, &so_far); });
  testing::run_program(
      in, kMaxOps, twin.graph(),
      [&](const Point& c, std::uint8_t s) { twin.run(TraceCommand::Kind::Refine, c, (s & 0x80) != 0); },
      [&](const Point& n, std::uint8_t s) { twin.run(TraceCommand::Kind::Coarsen, n, (s & 0x80) != 0); },
      [&](std::uint8_t s) {
        if (s & 0x40) twin.reseat((s & 0x20) != 0);
      });
  twin.compare_queries();
  return 0;
}
