#include "bccmis/invariants/checked.h"

#include <algorithm>
#include <iterator>

#include "bccmis/invariants/detail/lattice.h"
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

// The checks after an operation (defined below the wrappers, in call order).
void check_refine_result(const Graph& before, const Graph& g, const RefineResult& r, const Point& c,
                         const std::string& op);
void check_coarsen_result(const Graph& before, const Graph& g, const CoarsenResult& r, const Point& n,
                          const std::string& op);

}  // namespace

RefineResult checked_refine(Graph& g, const Point& c) {
  const std::string op = "refine " + inv::pos(c);
  validate(g, "before " + op);
  Graph before = g;
  RefineResult r = refine(g, c);
  try {
    check_refine_result(before, g, r, c, op);
  } catch (...) {
    // Strong guarantee: whatever failed after the operation (a violation, an
    // allocation in the checker), the caller gets the graph it passed in.
    g = std::move(before);  // a move of std::map/std::set members: no allocation
    throw;
  }
  return r;
}

namespace {

void check_refine_result(const Graph& before, const Graph& g, const RefineResult& r, const Point& c,
                         const std::string& op) {
  if (!r.applied()) {
    if (!(g == before))
      throw ViolationError(
          inv::violation(0, "refused-changed", {c},
                         op + " was refused (" + std::string(code(*r.refused)) + ") but changed the state", "§2.1 ¶1"),
          "after " + op);
    return;
  }
  validate(g, "after " + op);
  if (r.Y.size() != 4 || r.J_plus.size() > 4)
    throw ViolationError(inv::violation(0, "refine-count", points(r.Y, r.J_plus),
                                        op + " returned |Y| = " + std::to_string(r.Y.size()) + " and |J+| = " +
                                            std::to_string(r.J_plus.size()) + "; eq. (4a) and (5a) give 4 and 0..4",
                                        "§2.1 eq. (4a), (5a)"),
                         "after " + op);
  // eq. (4b), (4g): C = C ∪ Y \ {c}
  expect_change(before.C, g.C, r.Y, {c}, "C", op, "refine-count", "§2.1 eq. (4b), (4g)");
  // eq. (4h), (5b): N = N ∪ {c} ∪ J+
  PointSet gained = r.J_plus;
  gained.insert(c);
  expect_change(before.N, g.N, gained, {}, "N", op, "refine-count", "§2.1 eq. (4h), (5b)");
}

}  // namespace

CoarsenResult checked_coarsen(Graph& g, const Point& n) {
  const std::string op = "coarsen " + inv::pos(n);
  validate(g, "before " + op);
  Graph before = g;
  CoarsenResult r = coarsen(g, n);
  try {
    check_coarsen_result(before, g, r, n, op);
  } catch (...) {
    // Strong guarantee: whatever failed after the operation (a violation, an
    // allocation in the checker), the caller gets the graph it passed in.
    g = std::move(before);  // a move of std::map/std::set members: no allocation
    throw;
  }
  return r;
}

namespace {

void check_coarsen_result(const Graph& before, const Graph& g, const CoarsenResult& r, const Point& n,
                          const std::string& op) {
  if (!r.applied()) {
    if (!(g == before))
      throw ViolationError(
          inv::violation(0, "refused-changed", {n},
                         op + " was refused (" + std::string(code(*r.refused)) + ") but changed the state", "§2.2 ¶1"),
          "after " + op);
    return;
  }
  validate(g, "after " + op);
  if (r.Y.size() != 4 || r.J_minus.size() > 4)
    throw ViolationError(inv::violation(0, "coarsen-count", points(r.Y, r.J_minus),
                                        op + " returned |Y| = " + std::to_string(r.Y.size()) + " and |J-| = " +
                                            std::to_string(r.J_minus.size()) + "; eq. (8a) and (10a) give 4 and 0..4",
                                        "§2.2 eq. (8a), (10a)"),
                         "after " + op);
  // eq. (9e), (9f): C = C ∪ {n} \ Y
  expect_change(before.C, g.C, {n}, r.Y, "C", op, "coarsen-count", "§2.2 eq. (9e), (9f)");
  // eq. (9d), (10c): N = N \ {n} \ J-
  PointSet lost = r.J_minus;
  lost.insert(n);
  expect_change(before.N, g.N, {}, lost, "N", op, "coarsen-count", "§2.2 eq. (9d), (10c)");
}

}  // namespace

}  // namespace bccmis
