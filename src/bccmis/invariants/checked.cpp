#include "bccmis/invariants/checked.h"

#include <algorithm>
#include <iterator>

#include "bccmis/invariants/detail/lattice_geometry.h"
#include "bccmis/invariants/detail/layers.h"

namespace bccmis {

namespace {

PointSet difference(const PointSet& a, const PointSet& b) {
  PointSet out;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::inserter(out, out.end()));
  return out;
}

std::string list(const PointSet& s) {
  std::string out = "{";
  for (const Point& p : s) out += (out.size() > 1 ? ", " : "") + inv::pos(p);
  return out + "}";
}

std::vector<Point> points(const PointSet& a, const PointSet& b = {}) {
  std::vector<Point> out(a.begin(), a.end());
  out.insert(out.end(), b.begin(), b.end());
  return out;
}

void validate(const Graph& g, const std::string& context) {
  if (auto v = find_violation(g)) throw ViolationError(*v, context);
}

// The exact change of one vertex set: `gained` and `lost` as expected.
void expect_change(const PointSet& before, const PointSet& after, const PointSet& gained, const PointSet& lost,
                   const char* set_name, const std::string& op, const char* code, const char* section) {
  const PointSet plus = difference(after, before), minus = difference(before, after);
  if (plus == gained && minus == lost) return;
  const std::string text = op + " changed " + set_name + " by +" + list(plus) + " -" + list(minus) +
                           "; the equations give +" + list(gained) + " -" + list(lost);
  throw ViolationError(inv::violation(0, code, points(plus, minus), text, section), "after " + op);
}

// The sets an operation returned: |Y| = 4 centers and 0..4 junctions
// (`J_name`: J+ or J-), as `equations` give.
void expect_counts(const PointSet& Y, const PointSet& J, const char* J_name, const std::string& op, const char* code,
                   const char* equations, const char* section) {
  if (Y.size() == 4 && J.size() <= 4) return;
  throw ViolationError(inv::violation(0, code, points(Y, J),
                                      op + " returned |Y| = " + std::to_string(Y.size()) + " and |" + J_name +
                                          "| = " + std::to_string(J.size()) + "; " + equations + " give 4 and 0..4",
                                      section),
                       "after " + op);
}

// Runs op(g, at) between the checks: g must be valid before, and
// check(before, g, result, at, text) passes after, `text` being "verb (x, y)".
// Strong guarantee: whatever failed after the operation (a violation, an
// allocation in the checker), the caller gets the graph it passed in.
template <class Op, class Check>
auto run_checked(Graph& g, const Point& at, const char* verb, Op op, Check check) {
  const std::string text = verb + inv::pos(at);
  validate(g, "before " + text);
  Graph before = g;
  auto r = op(g, at);
  try {
    check(before, g, r, at, text);
  } catch (...) {
    g = std::move(before);  // a move of std::map/std::set members: no allocation
    throw;
  }
  return r;
}

// A refused operation must leave the graph as it was (true: refused);
// an applied one must leave it valid (false: go on checking).
template <class Result>
bool refused_unchanged(const Graph& before, const Graph& g, const Result& r, const Point& at, const std::string& op,
                       const char* section) {
  if (!r.applied()) {
    if (!(g == before))
      throw ViolationError(
          inv::violation(0, "refused-changed", {at},
                         op + " was refused (" + std::string(code(*r.refused)) + ") but changed the state", section),
          "after " + op);
    return true;
  }
  validate(g, "after " + op);
  return false;
}

void check_refine_result(const Graph& before, const Graph& g, const RefineResult& r, const Point& c,
                         const std::string& op) {
  if (refused_unchanged(before, g, r, c, op, "§2.1 ¶1")) return;
  expect_counts(r.Y, r.J_plus, "J+", op, "refine-count", "eq. (4a) and (5a)", "§2.1 eq. (4a), (5a)");
  // eq. (4b), (4g): C = C ∪ Y \ {c}
  expect_change(before.C, g.C, r.Y, {c}, "C", op, "refine-count", "§2.1 eq. (4b), (4g)");
  // eq. (4h), (5b): N = N ∪ {c} ∪ J+
  PointSet gained = r.J_plus;
  gained.insert(c);
  expect_change(before.N, g.N, gained, {}, "N", op, "refine-count", "§2.1 eq. (4h), (5b)");
}

void check_coarsen_result(const Graph& before, const Graph& g, const CoarsenResult& r, const Point& n,
                          const std::string& op) {
  if (refused_unchanged(before, g, r, n, op, "§2.2 ¶1")) return;
  expect_counts(r.Y, r.J_minus, "J-", op, "coarsen-count", "eq. (8a) and (10a)", "§2.2 eq. (8a), (10a)");
  // eq. (9e), (9f): C = C ∪ {n} \ Y
  expect_change(before.C, g.C, {n}, r.Y, "C", op, "coarsen-count", "§2.2 eq. (9e), (9f)");
  // eq. (9d), (10c): N = N \ {n} \ J-
  PointSet lost = r.J_minus;
  lost.insert(n);
  expect_change(before.N, g.N, {}, lost, "N", op, "coarsen-count", "§2.2 eq. (9d), (10c)");
}

}  // namespace

RefineResult checked_refine(Graph& g, const Point& c) {
  return run_checked(
      g, c, "refine ", [](Graph& h, const Point& p) { return refine(h, p); }, check_refine_result);
}

CoarsenResult checked_coarsen(Graph& g, const Point& n) {
  return run_checked(
      g, n, "coarsen ", [](Graph& h, const Point& p) { return coarsen(h, p); }, check_coarsen_result);
}

}  // namespace bccmis
