// Shared RapidCheck generators and property bodies for the property suites
// (tests/properties_test.cpp, tests/model_test.cpp, tests/mutants/,
// tests/fast/differential_test.cpp).
//
// A Scenario is a lattice size plus a list of Steps. A Step is generated
// without looking at any state and resolved against the current graph only
// when it runs, so scenarios shrink well (fewer steps, smaller indices) and
// the shrunk counterexample still means something:
//   - Pick::Live       refine a live cell center / coarsen a node that sits at
//                      the center of a refinable cell (biased to legal ops);
//   - Pick::WrongKind  refine a node / coarsen a cell center (always illegal);
//   - Pick::Anywhere   any integer position in and around the domain (mostly
//                      illegal: not a vertex, or the wrong kind).
// Every failure message ends with the trace (spec/formats.md) of the commands
// run so far, ready to be saved in tests/regressions/.
//
// The property bodies take the operations under test as an Ops value so that
// tests/mutants/ can run the same properties against planted bugs.
#pragma once

#include <gtest/gtest.h>  // must come before rapidcheck/gtest.h
#include <rapidcheck.h>

#include <cstdint>
#include <exception>
#include <functional>
#include <iterator>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/graph.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"
#include "bccmis/ops.h"
#include "model/leaf_model.h"

namespace bccmis::proptest {

// ---- The operations under test ---------------------------------------------

struct Ops {
  std::string name = "core";
  std::function<RefineResult(Graph&, const Point&)> refine = [](Graph& g, const Point& c) {
    return bccmis::refine(g, c);
  };
  std::function<CoarsenResult(Graph&, const Point&)> coarsen = [](Graph& g, const Point& n) {
    return bccmis::coarsen(g, n);
  };
  std::function<std::optional<RefineRefusal>(const Graph&, const Point&)> can_refine =
      [](const Graph& g, const Point& c) { return bccmis::can_refine(g, c); };
  std::function<std::optional<CoarsenRefusal>(const Graph&, const Point&)> can_coarsen =
      [](const Graph& g, const Point& n) { return bccmis::can_coarsen(g, n); };
};

// ---- Steps and scenarios ----------------------------------------------------

enum class OpKind { Refine, Coarsen };
enum class Pick { Live, WrongKind, Anywhere };

/// The trace command kind of an operation.
inline TraceCommand::Kind trace_kind(OpKind op) {
  return op == OpKind::Refine ? TraceCommand::Kind::Refine : TraceCommand::Kind::Coarsen;
}

struct Step {
  OpKind op = OpKind::Refine;
  Pick pick = Pick::Live;
  std::uint32_t a = 0;  ///< index into the candidates, or the x of an Anywhere position
  std::uint32_t b = 0;  ///< the y of an Anywhere position
};

inline std::ostream& operator<<(std::ostream& os, const Step& s) {
  os << (s.op == OpKind::Refine ? "refine" : "coarsen");
  switch (s.pick) {
    case Pick::Live: return os << " live#" << s.a;
    case Pick::WrongKind: return os << " wrong-kind#" << s.a;
    case Pick::Anywhere: return os << " anywhere(" << s.a << "," << s.b << ")";
  }
  return os;
}

struct Scenario {
  Scenario() = default;
  Scenario(LatticeSize s, std::vector<Step> st) : size(s), steps(std::move(st)) {}
  LatticeSize size;
  std::vector<Step> steps;
};

inline std::ostream& operator<<(std::ostream& os, const Scenario& sc) {
  os << "lattice " << sc.size.W << " " << sc.size.H << " " << sc.size.L << "; " << sc.steps.size() << " steps:";
  for (const Step& s : sc.steps) os << " [" << s << "]";
  return os;
}

/// W, H in 1..4 and L in 0..3, weighted towards lattices with room to refine.
inline rc::Gen<LatticeSize> genLatticeSize() {
  return rc::gen::map(rc::gen::tuple(rc::gen::inRange<std::int64_t>(1, 5), rc::gen::inRange<std::int64_t>(1, 5),
                                     rc::gen::weightedElement<int>({{1, 0}, {3, 1}, {4, 2}, {2, 3}})),
                      [](const std::tuple<std::int64_t, std::int64_t, int>& t) {
                        LatticeSize s;
                        s.W = std::get<0>(t);
                        s.H = std::get<1>(t);
                        s.L = std::get<2>(t);
                        return s;
                      });
}

/// Steps whose operation and pick are drawn from `ops` and `picks`.
inline rc::Gen<Step> genStep(rc::Gen<OpKind> ops, rc::Gen<Pick> picks) {
  return rc::gen::map(rc::gen::tuple(std::move(ops), std::move(picks), rc::gen::arbitrary<std::uint32_t>(),
                                     rc::gen::arbitrary<std::uint32_t>()),
                      [](const std::tuple<OpKind, Pick, std::uint32_t, std::uint32_t>& t) {
                        Step s;
                        s.op = std::get<0>(t);
                        s.pick = std::get<1>(t);
                        s.a = std::get<2>(t);
                        s.b = std::get<3>(t);
                        return s;
                      });
}

inline rc::Gen<Step> genStep() {
  return genStep(rc::gen::weightedElement<OpKind>({{3, OpKind::Refine}, {2, OpKind::Coarsen}}),
                 rc::gen::weightedElement<Pick>({{7, Pick::Live}, {1, Pick::WrongKind}, {2, Pick::Anywhere}}));
}

/// Up to max_steps steps (scaled by RapidCheck's size; max_size 100 gives the full range).
inline rc::Gen<std::vector<Step>> genSteps(int max_steps = 50) {
  return rc::gen::scale(max_steps / 100.0, rc::gen::container<std::vector<Step>>(genStep()));
}

inline rc::Gen<Scenario> genScenario(int max_steps = 50) {
  return rc::gen::map(
      rc::gen::tuple(genLatticeSize(), genSteps(max_steps)),
      [](const std::tuple<LatticeSize, std::vector<Step>>& t) { return Scenario(std::get<0>(t), std::get<1>(t)); });
}

// ---- Geometry from the independent leaf model -------------------------------

inline model::Lattice model_lattice(const LatticeSize& s) {
  return model::Lattice{static_cast<int>(s.W), static_cast<int>(s.H), s.L};
}
inline model::Pos model_pos(const Point& p) { return model::Pos{p.x, p.y}; }
inline model::State model_initial(const LatticeSize& s) {
  return model::initial_state(static_cast<int>(s.W), static_cast<int>(s.H), s.L);
}

/// The model's decision for an operation at p: "ok" or the refusal code.
inline std::string model_decision(const model::State& m, OpKind op, const Point& p) {
  if (op == OpKind::Refine) return std::string(model::to_string(model::check_refine_at(m, model_pos(p))));
  return std::string(model::to_string(model::check_coarsen_at(m, model_pos(p))));
}

/// Applies an operation the model accepts at p.
inline void model_apply(model::State& m, OpKind op, const Point& p) {
  const std::optional<model::Leaf> cell = model::cell_at_center(m.lat, model_pos(p));
  if (!cell) throw std::logic_error("model_apply: no cell centered at the position");
  if (op == OpKind::Refine)
    model::apply_refine(m, *cell);
  else
    model::apply_coarsen(m, *cell);
}

/// The cells (center, level) and nodes (every leaf corner) the model implies.
struct Projection {
  std::set<std::pair<Point, int>> centers;
  PointSet nodes;
};

inline Projection project(const model::State& m) {
  Projection p;
  for (const model::Leaf& leaf : m.leaves) {
    const model::Pos c = model::center_of(m.lat, leaf);
    p.centers.insert({Point{c.x, c.y}, leaf.level});
    const model::Rect r = model::rect_of(m.lat, leaf);
    for (const Point q : {Point{r.x0, r.y0}, Point{r.x1, r.y0}, Point{r.x0, r.y1}, Point{r.x1, r.y1}})
      p.nodes.insert(q);
  }
  return p;
}

inline std::string point_text(const Point& p) { return to_string(p); }

/// Empty when g's centers (position, level) are exactly the model's leaves and
/// g's nodes exactly the leaves' corners; otherwise the first difference.
inline std::optional<std::string> projection_mismatch(const Graph& g, const model::State& m) {
  const Projection want = project(m);
  std::set<std::pair<Point, int>> have;
  for (const Point& c : g.C) {
    const auto it = g.level.find(c);
    have.insert({c, it == g.level.end() ? -1 : it->second});
  }
  for (const auto& [c, l] : want.centers)
    if (have.count({c, l}) == 0)
      return "the model has a level-" + std::to_string(l) + " leaf centered at " + point_text(c) +
             ", the graph has no such center";
  for (const auto& [c, l] : have)
    if (want.centers.count({c, l}) == 0)
      return "the graph has a center " + point_text(c) + " of level " + std::to_string(l) +
             " that is no leaf of the model";
  for (const Point& n : want.nodes)
    if (g.N.count(n) == 0) return "the leaf corner " + point_text(n) + " is not a node of the graph";
  for (const Point& n : g.N)
    if (want.nodes.count(n) == 0) return "the graph node " + point_text(n) + " is no corner of any model leaf";
  return std::nullopt;
}

// ---- Running steps ----------------------------------------------------------

template <class Set>
typename Set::value_type nth(const Set& set, std::uint32_t index) {
  auto it = set.begin();
  std::advance(it, static_cast<std::ptrdiff_t>(index % set.size()));
  return *it;
}

/// The position a step names in graph g.
inline Point resolve(const Graph& g, const Step& s) {
  const std::int64_t S = level0_side(g.size);
  switch (s.pick) {
    case Pick::Live:
      if (s.op == OpKind::Refine) return nth(g.C, s.a);
      {
        // Nodes at the center of a cell that can be refined, found from the
        // model's geometry (not the core's position helpers).
        const model::Lattice lat = model_lattice(g.size);
        std::vector<Point> candidates;
        for (const Point& n : g.N) {
          const auto cell = model::cell_at_center(lat, model_pos(n));
          if (cell && cell->level < lat.L) candidates.push_back(n);
        }
        if (!candidates.empty()) return candidates[s.a % candidates.size()];
        return nth(g.N, s.a);
      }
    case Pick::WrongKind: return s.op == OpKind::Refine ? nth(g.N, s.a) : nth(g.C, s.a);
    case Pick::Anywhere:
      return Point{static_cast<std::int64_t>(s.a % static_cast<std::uint64_t>(g.size.W * S + 5)) - 2,
                   static_cast<std::int64_t>(s.b % static_cast<std::uint64_t>(g.size.H * S + 5)) - 2};
  }
  return Point{};
}

/// What one operation did.
struct Outcome {
  OpKind op = OpKind::Refine;
  Point at;
  bool applied = false;
  std::string code;  ///< "ok" or the refusal code
  RefineResult refine;
  CoarsenResult coarsen;
};

/// A graph driven by steps, with the trace of what ran (and, optionally, the
/// leaf model kept in step: every accepted operation is applied to it too,
/// after the caller compared the decisions).
class Walk {
 public:
  Walk(Ops ops, const LatticeSize& size) : ops_(std::move(ops)), g_(make_lattice(size)), m_(model_initial(size)) {
    trace_.size = size;
  }

  const Graph& graph() const { return g_; }
  Graph& graph() { return g_; }
  const model::State& model() const { return m_; }
  const Ops& ops() const { return ops_; }
  const Trace& trace() const { return trace_; }

  /// Fails the current RapidCheck case with msg and the trace so far.
  [[noreturn]] void fail(const std::string& msg) const {
    std::ostringstream os;
    os << "[" << ops_.name << "] " << msg << "\nreproducer trace:\n" << format_trace(trace_);
    RC_FAIL(os.str());
    throw std::logic_error("unreachable");  // RC_FAIL throws; keeps [[noreturn]] honest
  }

  void require(bool ok, const std::string& msg) const {
    if (!ok) fail(msg);
  }

  /// Runs op at p with the operations under test (records it in the trace).
  Outcome run(OpKind op, const Point& p) {
    trace_.commands.push_back(TraceCommand{trace_kind(op), p, 0});
    Outcome o;
    o.op = op;
    o.at = p;
    try {
      if (op == OpKind::Refine) {
        o.refine = ops_.refine(g_, p);
        o.applied = o.refine.applied();
        o.code = o.applied ? "ok" : std::string(code(*o.refine.refused));
      } else {
        o.coarsen = ops_.coarsen(g_, p);
        o.applied = o.coarsen.applied();
        o.code = o.applied ? "ok" : std::string(code(*o.coarsen.refused));
      }
    } catch (const std::exception& e) {
      fail(std::string(op == OpKind::Refine ? "refine " : "coarsen ") + point_text(p) + " threw: " + e.what());
    }
    return o;
  }

  Outcome run(const Step& s) { return run(s.op, resolve(g_, s)); }

  /// The model's decision for op at p in the current state.
  std::string expected(OpKind op, const Point& p) const { return model_decision(m_, op, p); }

  /// Requires the graph's decision to equal the model's, then keeps the model in step.
  void sync_model(const Outcome& o, const std::string& expected_code) {
    if (o.code != expected_code)
      fail(std::string(o.op == OpKind::Refine ? "refine " : "coarsen ") + point_text(o.at) + ": the graph says " +
           o.code + ", the geometric rule (leaf model) says " + expected_code);
    if (o.applied) model_apply(m_, o.op, o.at);
  }

 private:
  Ops ops_;
  Graph g_;
  model::State m_;
  Trace trace_;
};

inline std::string describe(const Outcome& o) {
  return std::string(o.op == OpKind::Refine ? "refine " : "coarsen ") + point_text(o.at) + " (" + o.code + ")";
}

// ---- Property bodies --------------------------------------------------------

/// Every state after every operation passes the full checker (layers 1-4).
inline void prop_valid_after_every_op(const Ops& ops, const Scenario& sc) {
  Walk w(ops, sc.size);
  if (const auto v = find_violation(w.graph())) w.fail("the initial lattice is invalid: " + to_string(*v));
  for (const Step& s : sc.steps) {
    const Outcome o = w.run(s);
    if (const auto v = find_violation(w.graph())) w.fail("after " + describe(o) + ": " + to_string(*v));
  }
}

/// §3: each applied `op` followed by `inverse` at the same position gives
/// back the byte-identical canonical state.
inline void prop_inverse_restores(const Ops& ops, const Scenario& sc, OpKind op, OpKind inverse) {
  const std::string op_name = op == OpKind::Refine ? "refine" : "coarsen";
  const std::string inverse_name = inverse == OpKind::Refine ? "refine" : "coarsen";
  const std::string op_gerund = op == OpKind::Refine ? "refining" : "coarsening";
  Walk w(ops, sc.size);
  for (const Step& s : sc.steps) {
    const std::string before = canonical_state(w.graph());
    const Outcome o = w.run(s);
    if (!o.applied || o.op != op) continue;
    Walk back = w;  // the walk goes on from the state after op
    const Outcome u = back.run(inverse, o.at);
    back.require(u.applied, inverse_name + " " + point_text(o.at) + " right after " + op_gerund + " it was refused (" +
                                u.code + ")");
    back.require(canonical_state(back.graph()) == before, op_name + " " + point_text(o.at) + " then " + inverse_name +
                                                              " " + point_text(o.at) +
                                                              " does not give back the canonical state");
  }
}

/// §3: refine(c) then coarsen(c) gives back the byte-identical canonical state.
inline void prop_refine_then_coarsen(const Ops& ops, const Scenario& sc) {
  prop_inverse_restores(ops, sc, OpKind::Refine, OpKind::Coarsen);
}

/// §3: coarsen(n) then refine(n) gives back the byte-identical canonical state.
inline void prop_coarsen_then_refine(const Ops& ops, const Scenario& sc) {
  prop_inverse_restores(ops, sc, OpKind::Coarsen, OpKind::Refine);
}

/// A refused operation leaves the canonical state byte-identical, and its code
/// is the one the geometric rule gives (spec/formats.md, refusal codes).
inline void prop_refusal_leaves_state_unchanged(const Ops& ops, const Scenario& sc) {
  Walk w(ops, sc.size);
  for (const Step& s : sc.steps) {
    const Point p = resolve(w.graph(), s);
    const std::string expected = w.expected(s.op, p);
    const std::string before = canonical_state(w.graph());
    const Outcome o = w.run(s.op, p);
    if (!o.applied) w.require(canonical_state(w.graph()) == before, "refused " + describe(o) + " changed the state");
    w.sync_model(o, expected);
  }
}

/// The vertex counts change by exactly what the equations imply:
/// refine: |C| + 3 (4b, 4g), |N| + 1 + (4 - |J|) (4h, 5a, 5b), |Y| = 4;
/// coarsen: |C| - 3 (9e, 9f), |N| - 1 - |J-| (9d, 10c), |Y| = 4;
/// and after every step |C| = #leaves and |N| = #leaf corners of the model.
inline void prop_vertex_counts(const Ops& ops, const Scenario& sc) {
  Walk w(ops, sc.size);
  for (const Step& s : sc.steps) {
    const Graph& g = w.graph();
    const Point p = resolve(g, s);
    const std::string expected = w.expected(s.op, p);
    const auto n0 = static_cast<std::int64_t>(g.N.size());
    const auto c0 = static_cast<std::int64_t>(g.C.size());
    // J of eq. (2b): the nodes of the cell with three neighbors.
    std::int64_t junctions = 0;
    if (s.op == OpKind::Refine)
      for (const Point& b : g.nbr(p))
        if (g.nbr(b).size() == 3) ++junctions;
    const Outcome o = w.run(s.op, p);
    const auto dn = static_cast<std::int64_t>(g.N.size()) - n0;
    const auto dc = static_cast<std::int64_t>(g.C.size()) - c0;
    const std::string what = describe(o) + ": |N| changed by " + std::to_string(dn) + ", |C| by " + std::to_string(dc);
    if (!o.applied) {
      w.require(dn == 0 && dc == 0, what + ", expected no change");
    } else if (o.op == OpKind::Refine) {
      w.require(dc == 3, what + ", expected |C| + 3");
      w.require(dn == 1 + (4 - junctions),
                what + ", expected |N| + " + std::to_string(1 + 4 - junctions) + " (c and 4 - |J| new junctions)");
      w.require(o.refine.Y.size() == 4, what + ": |Y| = " + std::to_string(o.refine.Y.size()));
      w.require(static_cast<std::int64_t>(o.refine.J_plus.size()) == 4 - junctions,
                what + ": |J+| = " + std::to_string(o.refine.J_plus.size()));
    } else {
      w.require(dc == -3, what + ", expected |C| - 3");
      w.require(dn == -1 - static_cast<std::int64_t>(o.coarsen.J_minus.size()),
                what + ", expected |N| - 1 - |J-| = " +
                    std::to_string(-1 - static_cast<std::int64_t>(o.coarsen.J_minus.size())));
      w.require(o.coarsen.Y.size() == 4, what + ": |Y| = " + std::to_string(o.coarsen.Y.size()));
    }
    w.sync_model(o, expected);
    const Projection want = project(w.model());
    w.require(g.C.size() == want.centers.size(), "after " + describe(o) + ": |C| = " + std::to_string(g.C.size()) +
                                                     ", the model has " + std::to_string(want.centers.size()) +
                                                     " leaves");
    w.require(g.N.size() == want.nodes.size(), "after " + describe(o) + ": |N| = " + std::to_string(g.N.size()) +
                                                   ", the model's leaves have " + std::to_string(want.nodes.size()) +
                                                   " corners");
  }
}

/// From any state, coarsening every coarsenable node, pass after pass, ends in
/// the initial lattice (byte-identical canonical state).
inline void prop_coarsen_everything(const Ops& ops, const Scenario& sc) {
  Walk w(ops, sc.size);
  for (const Step& s : sc.steps) w.run(s);
  const std::string initial = canonical_state(make_lattice(sc.size));
  // Each pass removes at least the finest level; 2 * (L + 1) passes are plenty.
  for (int pass = 0; pass <= 2 * (sc.size.L + 1); ++pass) {
    bool changed = false;
    const PointSet nodes = w.graph().N;
    for (const Point& n : nodes)
      if (w.graph().is_node(n) && w.run(OpKind::Coarsen, n).applied) changed = true;
    if (!changed) break;
  }
  w.require(canonical_state(w.graph()) == initial,
            "coarsening everything possible did not give back the initial lattice; " +
                std::to_string(w.graph().C.size()) + " cells are left");
}

/// Refine and coarsen are accepted iff the geometric rule (the leaf model,
/// written without the graph code) accepts them, with the same refusal code:
/// for the operation of every step, and for can_refine / can_coarsen on every
/// vertex (and a ring of positions around the domain) of every state.
inline void prop_decisions_match_geometry(const Ops& ops, const Scenario& sc) {
  Walk w(ops, sc.size);
  const std::int64_t S = level0_side(sc.size);
  auto check_all = [&](const std::string& when) {
    const Graph& g = w.graph();
    auto compare = [&](OpKind op, const Point& p) {
      const std::string want = w.expected(op, p);
      std::string have;
      if (op == OpKind::Refine) {
        const auto r = w.ops().can_refine(g, p);
        have = r ? std::string(code(*r)) : "ok";
      } else {
        const auto r = w.ops().can_coarsen(g, p);
        have = r ? std::string(code(*r)) : "ok";
      }
      if (have != want)
        w.fail(when + ": can_" + (op == OpKind::Refine ? "refine " : "coarsen ") + point_text(p) + " says " + have +
               ", the geometric rule says " + want);
    };
    for (const Point& c : g.C) {
      compare(OpKind::Refine, c);
      compare(OpKind::Coarsen, c);
    }
    for (const Point& n : g.N) {
      compare(OpKind::Refine, n);
      compare(OpKind::Coarsen, n);
    }
    for (const Point& p : {Point{-1, -1}, Point{g.size.W * S + 1, 0}, Point{0, g.size.H * S + 2},
                           Point{g.size.W * S / 2 + 1, g.size.H * S / 2}}) {
      compare(OpKind::Refine, p);
      compare(OpKind::Coarsen, p);
    }
  };
  check_all("initial lattice");
  for (const Step& s : sc.steps) {
    const Point p = resolve(w.graph(), s);
    const std::string expected = w.expected(s.op, p);
    const Outcome o = w.run(s.op, p);
    w.sync_model(o, expected);
    check_all("after " + describe(o));
  }
}

// ---- Replaying a trace with every per-step check ---------------------------

/// Replays `trace` with `ops` and, after every refine/coarsen, checks what the
/// properties check: the decision (ok or refusal code) equals the leaf
/// model's, a refused call leaves the canonical state unchanged, an accepted
/// one is undone exactly by its inverse, and the state passes the checker.
/// Returns the first problem (with the command's line), or nothing.
inline std::optional<std::string> check_trace(const Ops& ops, const Trace& trace) {
  Graph g = make_lattice(trace.size);
  model::State m = model_initial(trace.size);
  for (const TraceCommand& cmd : trace.commands) {
    if (cmd.kind == TraceCommand::Kind::Check) continue;
    const OpKind op = cmd.kind == TraceCommand::Kind::Refine ? OpKind::Refine : OpKind::Coarsen;
    const std::string where = "line " + std::to_string(cmd.line) + " (" + command_text(cmd) + "): ";
    const std::string expected = model_decision(m, op, cmd.at);
    const std::string before = canonical_state(g);
    try {
      std::string have;
      if (op == OpKind::Refine) {
        const RefineResult r = ops.refine(g, cmd.at);
        have = r.refused ? std::string(code(*r.refused)) : "ok";
      } else {
        const CoarsenResult r = ops.coarsen(g, cmd.at);
        have = r.refused ? std::string(code(*r.refused)) : "ok";
      }
      if (have != expected) return where + "the graph says " + have + ", the leaf model says " + expected;
      if (have != "ok") {
        if (canonical_state(g) != before) return where + "refused (" + have + ") but changed the state";
        continue;
      }
      model_apply(m, op, cmd.at);
      if (const auto v = find_violation(g)) return where + to_string(*v);
      Graph back = g;
      const bool undone =
          op == OpKind::Refine ? ops.coarsen(back, cmd.at).applied() : ops.refine(back, cmd.at).applied();
      if (!undone || canonical_state(back) != before) return where + "the inverse operation does not restore the state";
    } catch (const std::exception& e) {
      return where + "threw: " + e.what();
    }
  }
  return std::nullopt;
}

}  // namespace bccmis::proptest
