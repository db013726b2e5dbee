#include "bccmis/oracle/view.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string_view>
#include <variant>

#include "bccmis/oracle/oracle.h"
#include "bccmis/trace.h"
#include "view_template.h"  // generated: kViewTemplate, the page with a placeholder for the model

namespace bccmis {

namespace {

constexpr std::size_t kVerifyEvery = 64;
constexpr std::int64_t kMaxPageCoordinate = std::int64_t{1} << 53;
constexpr std::string_view kPlaceholder = "{\"format\": \"placeholder\"}";

void append_point(std::string& out, const Point& p) {
  out += std::to_string(p.x);
  out += ',';
  out += std::to_string(p.y);
}

/// [x,y,x,y,...]
std::string points_json(const std::vector<Point>& ps) {
  std::string out = "[";
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (i) out += ',';
    append_point(out, ps[i]);
  }
  return out + "]";
}
std::string points_json(const PointSet& s) { return points_json(std::vector<Point>(s.begin(), s.end())); }

bool has_vertex(const Graph& g, const Point& p) { return g.is_center(p) || g.is_node(p); }

int level_or(const Graph& g, const Point& p, int fallback) {
  const auto it = g.level.find(p);
  return it == g.level.end() ? fallback : it->second;
}

/// A vertex record: [x,y,level,nx,ny,...]; level -1 marks a node.
void append_record(std::string& out, const Graph& g, const Point& p) {
  out += '[';
  append_point(out, p);
  out += ',';
  out += std::to_string(g.is_center(p) ? level_or(g, p, 0) : -1);
  for (const Point& n : g.nbr(p)) {
    out += ',';
    append_point(out, n);
  }
  out += ']';
}

bool same_record(const Graph& a, const Graph& b, const Point& p) {
  const bool ca = a.is_center(p), cb = b.is_center(p);
  if (ca != cb || has_vertex(a, p) != has_vertex(b, p)) return false;
  if (ca && level_or(a, p, 0) != level_or(b, p, 0)) return false;
  return a.nbr(p) == b.nbr(p);
}

/// Every vertex position of g, sorted.
std::vector<Point> vertices(const Graph& g) {
  std::vector<Point> v;
  v.reserve(g.N.size() + g.C.size());
  std::merge(g.N.begin(), g.N.end(), g.C.begin(), g.C.end(), std::back_inserter(v));
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

/// The positions whose records differ between a and b (sorted).
std::vector<Point> changed_positions(const Graph& a, const Graph& b) {
  const std::vector<Point> va = vertices(a), vb = vertices(b);
  std::vector<Point> all;
  all.reserve(va.size() + vb.size());
  std::set_union(va.begin(), va.end(), vb.begin(), vb.end(), std::back_inserter(all));
  std::vector<Point> changed;
  for (const Point& p : all)
    if (!same_record(a, b, p)) changed.push_back(p);
  return changed;
}

std::string state_json(const Graph& g) {
  std::string out = "[";
  bool first = true;
  for (const Point& p : vertices(g)) {
    if (!first) out += ',';
    first = false;
    append_record(out, g, p);
  }
  return out + "]";
}

std::string violation_json(const Violation& v) {
  return "{\"code\":" + json_string(v.code, true) + ",\"message\":" + json_string(to_string(v), true) +
         ",\"layer\":" + std::to_string(v.layer) + ",\"where\":" + points_json(v.where) + "}";
}

/// Accumulates the model: the initial state, then one step per call.
class ModelBuilder {
 public:
  /// `total`: the number of steps including step 0 (for ViewOptions::check_last_only).
  ModelBuilder(const Graph& initial, const ViewOptions& o, std::string label, std::size_t total)
      : o_(o), prev_(initial), total_(total) {
    // JavaScript numbers are exact integers up to 2^53 only.
    const std::int64_t side = level0_side(initial.size);
    if (initial.size.W > kMaxPageCoordinate / side || initial.size.H > kMaxPageCoordinate / side)
      throw std::invalid_argument("lattice " + std::to_string(initial.size.W) + " " + std::to_string(initial.size.H) +
                                  " " + std::to_string(initial.size.L) +
                                  " is too large for the page: its coordinates exceed 2^53, where JavaScript numbers "
                                  "stop being exact integers");
    steps_ = "[";
    Step s;
    s.label = std::move(label);
    s.op = "initial";
    finish(s, initial, {});
  }

  struct Step {
    std::string label;  ///< what the step did, e.g. "refine 4 4" or a file name
    std::string op;     ///< initial, refine, coarsen, check, state
    int line = 0;       ///< trace line, 0 if none
    std::optional<Point> at;
    std::string decision;  ///< "ok", "refused <code>", or empty
    int level = -1;        ///< refine: level of c; coarsen: level of the new cell
    PointSet Y, J;         ///< refine: Y and J+; coarsen: removed Y and J-
  };

  /// A step whose changes are anywhere: compares every vertex.
  void add(const Step& s, const Graph& now) { finish(s, now, changed_positions(prev_, now)); }

  /// A refine or coarsen step: every edge the operation adds or removes has an
  /// end in `seeds` (c or n, Y, J+ or J-) or in their neighbor sets before or
  /// after, so only the two-ring of the seeds in both states is compared.
  /// Every `kVerifyEvery` steps the whole mirror is compared with `now`.
  void add_local(const Step& s, const Graph& now, PointSet seeds) {
    PointSet region = seeds;
    for (int ring = 0; ring < 2; ++ring) {
      PointSet next = region;
      for (const Point& p : region)
        for (const Graph* g : {static_cast<const Graph*>(&prev_), &now})
          next.insert(g->nbr(p).begin(), g->nbr(p).end());
      region = std::move(next);
    }
    std::vector<Point> changed;
    for (const Point& p : region)
      if (!same_record(prev_, now, p)) changed.push_back(p);
    finish(s, now, changed);
    if (count_ % kVerifyEvery == 0 && !(prev_ == now))
      throw std::logic_error("view: a step changed a vertex outside the two-ring of what it touched");
  }

  /// Throws std::logic_error unless the mirror the deltas built equals `now`.
  void verify(const Graph& now) const {
    if (!(prev_ == now)) throw std::logic_error("view: the deltas do not rebuild the final state");
  }

  /// A side state for step `step` (which must already have been added with `now` = the state there).
  void set_side(const ViewSide& side, const Graph& main_state) {
    side_ = "{\"step\":" + std::to_string(side.step) + ",\"title\":" + json_string(side.title, true) +
            ",\"message\":" + json_string(side.message, true);
    std::vector<Point> marks = side.marks;
    if (side.state) {
      const std::vector<Point> diff = changed_positions(main_state, *side.state);
      marks.insert(marks.end(), diff.begin(), diff.end());
      side_ += ",\"state\":" + state_json(*side.state);
      if (o_.check)
        if (const auto v = o_.check(*side.state)) side_ += ",\"v\":" + violation_json(*v);
    } else {
      side_ += ",\"state\":null";
    }
    side_ += ",\"marks\":" + points_json(marks) + "}";
  }

  ViewResult result(const Graph& initial) const {
    ViewResult r;
    r.steps = count_ - 1;
    r.first_violation = first_violation_;
    r.violation = violation_;
    const std::size_t open = o_.open_step ? std::min(*o_.open_step, count_ - 1) : first_violation_.value_or(0);
    r.json = "{\"format\":\"bccmis-view 1\",\"title\":" + json_string(o_.title, true) + ",\"lattice\":[" +
             std::to_string(initial.size.W) + "," + std::to_string(initial.size.H) + "," +
             std::to_string(initial.size.L) + "],\"open\":" + std::to_string(open) +
             ",\"init\":" + state_json(initial) + ",\"steps\":" + steps_ + "]" +
             (side_.empty() ? "" : ",\"side\":" + side_) + "}";
    const std::string_view tmpl = kViewTemplate;
    const std::size_t at = tmpl.find(kPlaceholder);
    if (at == std::string_view::npos) throw std::logic_error("view template has no model placeholder");
    r.html = std::string(tmpl.substr(0, at)) + r.json + std::string(tmpl.substr(at + kPlaceholder.size()));
    return r;
  }

 private:
  void finish(const Step& s, const Graph& now, const std::vector<Point>& changed) {
    std::string j = count_ ? "," : "";
    j += "{\"label\":" + json_string(s.label, true) + ",\"op\":\"" + s.op + "\"";
    if (s.line) j += ",\"line\":" + std::to_string(s.line);
    if (s.at) j += ",\"at\":" + points_json(std::vector<Point>{*s.at});
    if (!s.decision.empty()) j += ",\"decision\":" + json_string(s.decision, true);
    if (s.level >= 0) j += ",\"level\":" + std::to_string(s.level);
    if (!s.Y.empty()) j += ",\"Y\":" + points_json(s.Y);
    if (!s.J.empty()) j += ",\"J\":" + points_json(s.J);
    std::string set, del;
    for (const Point& p : changed) {
      if (has_vertex(now, p)) {
        if (!set.empty()) set += ',';
        append_record(set, now, p);
      } else {
        if (!del.empty()) del += ',';
        append_point(del, p);
      }
    }
    if (!set.empty()) j += ",\"set\":[" + set + "]";
    if (!del.empty()) j += ",\"del\":[" + del + "]";
    j += ",\"n\":[" + std::to_string(now.C.size()) + "," + std::to_string(now.N.size()) + "]";
    if (o_.check && (!o_.check_last_only || count_ + 1 == total_))
      if (const auto v = o_.check(now)) {
        j += ",\"v\":" + violation_json(*v);
        if (!first_violation_) {
          first_violation_ = count_;
          violation_ = to_string(*v);
        }
      }
    steps_ += j + "}";
    ++count_;
    // Bring prev_ up to `now` on the changed positions only.
    for (const Point& p : changed) {
      prev_.N.erase(p);
      prev_.C.erase(p);
      prev_.level.erase(p);
      prev_.neighbors.erase(p);
      if (now.is_node(p)) prev_.N.insert(p);
      if (now.is_center(p)) prev_.C.insert(p);
      if (const auto it = now.level.find(p); it != now.level.end()) prev_.level.insert(*it);
      if (const auto it = now.neighbors.find(p); it != now.neighbors.end()) prev_.neighbors.insert(*it);
    }
  }

  const ViewOptions& o_;
  Graph prev_;
  std::size_t total_;
  std::string steps_, side_;
  std::size_t count_ = 0;
  std::optional<std::size_t> first_violation_;
  std::string violation_;
};

std::string lattice_label(const LatticeSize& s) {
  return "lattice " + std::to_string(s.W) + " " + std::to_string(s.H) + " " + std::to_string(s.L);
}

/// The step of the page for one replayed command: its decision, and what it
/// touched (c, Y and J+ for refine; n, the removed Y and J- for coarsen).
ModelBuilder::Step trace_step(const TraceCommand& c, const Graph& g, const StepResult<Graph>& r) {
  ModelBuilder::Step s;
  s.label = command_text(c);
  s.line = c.line;
  if (const auto* refined = std::get_if<RefineResult>(&r.result)) {
    s.op = "refine";
    s.at = c.at;
    // The level of c before the step: its children's level minus one once applied.
    if (refined->applied())
      s.level = level_or(g, *refined->Y.begin(), 0) - 1;
    else
      s.level = g.is_center(c.at) ? level_or(g, c.at, -1) : -1;
    s.Y = refined->Y;
    s.J = refined->J_plus;
  } else if (const auto* coarsened = std::get_if<CoarsenResult>(&r.result)) {
    s.op = "coarsen";
    s.at = c.at;
    if (coarsened->applied()) s.level = level_or(g, c.at, -1);
    s.Y = coarsened->Y;
    s.J = coarsened->J_minus;
  } else {
    s.op = "check";
  }
  if (!r.is_check()) s.decision = r.applied() ? "ok" : "refused " + std::string(r.refusal());
  return s;
}

}  // namespace

ViewResult view_trace(const Trace& trace, const ViewOptions& o) {
  const Graph initial = make_lattice(trace.size);
  ModelBuilder model(initial, o, lattice_label(trace.size), trace.commands.size() + 1);
  std::optional<Graph> side_main;
  if (o.side && o.side->step == 0) side_main = initial;
  std::size_t step = 0;
  std::string log;
  const Graph g = replay<Graph>(
      trace, log, [&](const TraceCommand& c, const Graph& now, std::string_view, const StepResult<Graph>& r) {
        const ModelBuilder::Step s = trace_step(c, now, r);
        if (const auto vertices = static_cast<std::int64_t>(now.N.size() + now.C.size()); vertices > o.max_vertices)
          throw ViewLimitError(c.line, "after '" + s.label + "' the lattice has " + std::to_string(vertices) +
                                           " vertices, above the limit of " + std::to_string(o.max_vertices) +
                                           " (--max-vertices)");
        PointSet seeds = s.Y;
        seeds.insert(s.J.begin(), s.J.end());
        if (s.at) seeds.insert(*s.at);
        model.add_local(s, now, std::move(seeds));
        ++step;
        if (o.side && o.side->step == step) side_main = now;
      });
  if (o.side) {
    if (!side_main) throw std::invalid_argument("view: the side state's step is past the end of the trace");
    model.set_side(*o.side, *side_main);
  }
  model.verify(g);
  return model.result(initial);
}

ViewResult view_states(const std::vector<std::pair<std::string, Graph>>& states, const ViewOptions& o) {
  if (states.empty()) throw std::invalid_argument("view: no states");
  const Graph& initial = states.front().second;
  for (const auto& [name, g] : states)
    if (!(g.size == initial.size))
      throw std::invalid_argument(name + ": " + lattice_label(g.size) + " differs from the first state's " +
                                  lattice_label(initial.size));
  ModelBuilder model(initial, o, states.front().first, states.size());
  for (std::size_t i = 1; i < states.size(); ++i) {
    ModelBuilder::Step s;
    s.label = states[i].first;
    s.op = "state";
    model.add(s, states[i].second);
  }
  if (o.side) {
    if (o.side->step >= states.size()) throw std::invalid_argument("view: the side state's step is past the end");
    model.set_side(*o.side, states[o.side->step].second);
  }
  return model.result(initial);
}

}  // namespace bccmis
