// fuzz_differential_3d: the 3D reference (bccmis::d3::Graph) and
// bccmis::d3::fast::Lattice driven by the same operations; every observable must
// agree (issue "3D at scale").
//
// Input layout (every byte string is a valid program; past the end every
// byte is 0):
//   byte 0..3   W = 1 + b0 % 3, H = 1 + b1 % 3, D = 1 + b2 % 3, L = b3 % 5
//   then ops    selector byte s, then operands:
//     s & 7 == 0,1,2  refine the k-th live center of the reference  (k: 1 byte, 2 if |C| > 256)
//     s & 7 == 3,4    coarsen the k-th node at a refined cell's center (mostly legal)
//     s & 7 == 5      coarsen the k-th node of N (mostly refused)
//     s & 7 == 6      refine at a raw position (x, y, z)             (3 bytes; mostly refused)
//     s & 7 == 7      coarsen at a raw position (x, y, z)            (3 bytes; mostly refused)
//     s & 0x40        afterwards, the fast side goes on with a copy of itself
//   At most kMaxOps operations are decoded.
//
// After every operation (tests/testing/d3/twin.h): can_refine and can_coarsen
// at the position, the decision, Y and J+/J-, the counts, the canonical state
// byte for byte, and the fast lattice's own audit. At the end: every query at
// every vertex and around it. Any difference aborts with the equivalent text
// trace on stderr (and in $BCCMIS_FUZZ_TRACE), so `bccmis replay` reproduces it.
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "bccmis/d3/ops.h"
#include "bccmis/io/format.h"
#include "fuzz_util.h"
#include "testing/byte_program.h"
#include "testing/d3/twin.h"

namespace {

using namespace bccmis;

constexpr std::size_t kMaxOps = 96;
constexpr std::string_view kTarget = "fuzz_differential_3d";

template <class Set>
d3::Point nth(const Set& set, std::size_t k) {
  auto it = set.begin();
  std::advance(it, static_cast<std::ptrdiff_t>(k));
  return *it;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  testing::Bytes in(data, size);
  d3::LatticeSize lattice;
  lattice.W = 1 + in.next() % 3;
  lattice.H = 1 + in.next() % 3;
  lattice.D = 1 + in.next() % 3;
  lattice.L = in.next() % 5;
  d3::testing::Twin twin(lattice,
                         [](const std::string& what, const d3::Trace& so_far) { fuzz::fail(kTarget, what, &so_far); });
  const std::int64_t S = d3::level0_side(lattice);
  auto raw = [&](std::int64_t extent) { return static_cast<std::int64_t>(in.next()) % (extent + 3) - 1; };
  for (std::size_t op = 0; op < kMaxOps && !in.empty(); ++op) {
    const std::uint8_t s = in.next();
    const d3::Graph& g = twin.graph();
    switch (s & 7) {
      case 0:
      case 1:
      case 2: twin.run(CommandKind::Refine, nth(g.C, in.index(g.C.size()))); break;
      case 3:
      case 4: {
        std::vector<d3::Point> refined;
        for (const d3::Point& n : g.N)
          if (d3::refined_center_level(lattice, n)) refined.push_back(n);
        if (refined.empty()) break;
        twin.run(CommandKind::Coarsen, refined[in.index(refined.size())]);
        break;
      }
      case 5: twin.run(CommandKind::Coarsen, nth(g.N, in.index(g.N.size()))); break;
      default: {
        const std::int64_t x = raw(lattice.W * S), y = raw(lattice.H * S), z = raw(lattice.D * S);
        twin.run((s & 7) == 6 ? CommandKind::Refine : CommandKind::Coarsen, {x, y, z});
        break;
      }
    }
    if (s & 0x40) twin.reseat();
  }
  twin.compare_queries();
  return 0;
}
