// RapidCheck properties of the 3D lattice: any sequence of refine and coarsen
// (refusals included) keeps the graph equal to the geometric graph of its
// leaves, balanced, with the cardinality facts (tests/d3/check.h); a refusal
// changes nothing; refine then coarsen is the identity. The seed and budget
// are fixed in tests/d3/d3.cmake; a failure prints the shrunk operation list
// as a 3D trace and the reproduce string.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cstdint>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "check.h"
#include "util.h"

namespace bccmis::d3 {
namespace {

const LatticeSize kSizes[] = {{1, 1, 1, 2}, {2, 1, 1, 2}, {2, 2, 1, 2}, {1, 1, 1, 3}, {2, 2, 2, 1}};

// One operation: refine the k-th cell or coarsen the k-th node (k modulo the
// current count), so every generated sequence is meaningful in every state.
struct Op {
  bool refine;
  std::size_t k;
};

template <class Set>
Point nth(const Set& s, std::size_t k) {
  auto it = s.begin();
  std::advance(it, static_cast<long>(k % s.size()));
  return *it;
}

std::string point_text(const Point& p) {
  return std::to_string(p.x) + ' ' + std::to_string(p.y) + ' ' + std::to_string(p.z);
}

rc::Gen<std::vector<Op>> ops() {
  return rc::gen::container<std::vector<Op>>(rc::gen::construct<Op>(
      rc::gen::weightedElement<bool>({{3, true}, {2, false}}), rc::gen::inRange<std::size_t>(0, 4096)));
}

RC_GTEST_PROP(D3Properties, EveryStateIsTheGeometricGraphOfItsLeaves, ()) {
  //= bccmis3d#fact-F1 type=test
  //= bccmis3d#fact-F2 type=test
  //= bccmis3d#fact-F3 type=test
  const LatticeSize size = *rc::gen::elementOf(std::vector<LatticeSize>(std::begin(kSizes), std::end(kSizes)));
  const std::vector<Op> sequence = *rc::gen::resize(40, ops());
  Graph g(size);
  RC_LOG() << "lattice " << size.W << ' ' << size.H << ' ' << size.D << ' ' << size.L << '\n';
  for (const Op& op : sequence) {
    const std::string before = canonical_state(g);
    bool applied = false;
    if (op.refine) {
      const Point c = nth(g.C, op.k);
      RC_LOG() << "refine " << point_text(c) << '\n';
      applied = refine(g, c).applied();
    } else {
      // Coarsen targets are drawn from the refined-center positions when there
      // are any, so that coarsening happens.
      std::vector<Point> centers;
      for (const Point& v : g.N)
        if (refined_center_level(g.size, v)) centers.push_back(v);
      const Point n = centers.empty() ? nth(g.N, op.k) : nth(centers, op.k);
      RC_LOG() << "coarsen " << point_text(n) << '\n';
      applied = coarsen(g, n).applied();
    }
    if (!applied) RC_ASSERT(canonical_state(g) == before);
    RC_ASSERT(test::state_problem(g) == std::string());
  }
}

RC_GTEST_PROP(D3Properties, RefineThenCoarsenIsTheIdentity, ()) {
  //= bccmis3d#claim-inverse type=test
  const LatticeSize size = *rc::gen::elementOf(std::vector<LatticeSize>(std::begin(kSizes), std::end(kSizes)));
  const std::vector<Op> sequence = *rc::gen::resize(25, ops());
  Graph g(size);
  for (const Op& op : sequence) {
    const Point v = op.refine ? nth(g.C, op.k) : nth(g.N, op.k);
    if (op.refine)
      refine(g, v);
    else
      coarsen(g, v);
  }
  const Point c = nth(g.C, *rc::gen::inRange<std::size_t>(0, 4096));
  Graph h = g;
  RC_PRE(refine(h, c).applied());
  RC_ASSERT(coarsen(h, c).applied());
  RC_ASSERT(h == g);
}

}  // namespace
}  // namespace bccmis::d3
