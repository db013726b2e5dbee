#include "bccmis/explore/explore.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <deque>
#include <exception>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <thread>
#include <unordered_set>
#include <utility>
#include <vector>

#include "bccmis/format.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/trace.h"

namespace bccmis {
namespace {

// ---- The exact state key ----------------------------------------------------
//
// Two encodings, told apart by the first byte:
//
//  0 (compact): used when the graph is "regular": every point (vertex or
//    neighbor) lies on the integer grid [0, W*S] x [0, H*S], N and C are
//    disjoint, the keys of `neighbors` are exactly N ∪ C, the keys of `level`
//    are exactly C, and every level is in 0..200. Points are numbered
//    id = x * (H*S + 1) + y, which is increasing in the (x, y) order of Point.
//    Then, for each entry of `neighbors` in order:
//      varint(id - previous id)          (previous id starts at -1)
//      byte 0 for a node, 1 + level for a center
//      varint(|N(v)|)
//      zigzag varint(first neighbor id - id), varint(delta) for the others
//  1 (generic): anything else, every container written out with zigzag
//    varints of raw coordinates.
// Both are decodable, so the key is exact.

void put_varint(std::string& out, std::uint64_t v) {
  while (v >= 0x80) {
    out.push_back(static_cast<char>((v & 0x7f) | 0x80));
    v >>= 7;
  }
  out.push_back(static_cast<char>(v));
}

std::uint64_t zigzag(std::int64_t v) {
  return (static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63);
}

std::int64_t unzigzag(std::uint64_t v) { return static_cast<std::int64_t>(v >> 1) ^ -static_cast<std::int64_t>(v & 1); }

struct Reader {
  const std::string& s;
  std::size_t pos = 0;
  std::uint64_t varint() {
    std::uint64_t v = 0;
    for (int shift = 0;; shift += 7) {
      if (pos >= s.size() || shift > 63) throw std::invalid_argument("state key: truncated varint");
      const auto byte = static_cast<unsigned char>(s[pos++]);
      v |= static_cast<std::uint64_t>(byte & 0x7f) << shift;
      if ((byte & 0x80) == 0) return v;
    }
  }
  std::int64_t svarint() { return unzigzag(varint()); }
  unsigned char byte() {
    if (pos >= s.size()) throw std::invalid_argument("state key: truncated");
    return static_cast<unsigned char>(s[pos++]);
  }
  Point point() {
    const std::int64_t x = svarint();
    return Point{x, svarint()};
  }
};

struct Grid {
  std::int64_t xmax = 0, ymax = 0, stride = 1;
  explicit Grid(const LatticeSize& size) {
    const std::int64_t S = level0_side(size);
    xmax = size.W * S;
    ymax = size.H * S;
    stride = ymax + 1;
  }
  bool contains(const Point& p) const { return p.x >= 0 && p.y >= 0 && p.x <= xmax && p.y <= ymax; }
  std::int64_t id(const Point& p) const { return p.x * stride + p.y; }
  Point point(std::int64_t id) const { return Point{id / stride, id % stride}; }
};

bool encode_compact(const Graph& g, const Grid& grid, std::string& out) {
  out.clear();
  out.push_back('\0');
  put_varint(out, g.neighbors.size());
  auto n_it = g.N.begin();
  auto c_it = g.C.begin();
  auto l_it = g.level.begin();
  std::int64_t prev = -1;
  for (const auto& [v, nbrs] : g.neighbors) {
    if (!grid.contains(v)) return false;
    int tag;
    if (n_it != g.N.end() && *n_it == v) {
      if (c_it != g.C.end() && *c_it == v) return false;  // in N and C
      ++n_it;
      tag = 0;
    } else if (c_it != g.C.end() && *c_it == v && l_it != g.level.end() && l_it->first == v) {
      if (l_it->second < 0 || l_it->second > 200) return false;
      tag = 1 + l_it->second;
      ++c_it;
      ++l_it;
    } else {
      return false;  // a neighbors entry of a vertex that is neither (or a center without level)
    }
    const std::int64_t id = grid.id(v);
    put_varint(out, static_cast<std::uint64_t>(id - prev));
    prev = id;
    out.push_back(static_cast<char>(tag));
    put_varint(out, nbrs.size());
    std::int64_t prev_n = 0;
    bool first = true;
    for (const Point& w : nbrs) {
      if (!grid.contains(w)) return false;
      const std::int64_t wid = grid.id(w);
      if (first) {
        put_varint(out, zigzag(wid - id));
        first = false;
      } else {
        put_varint(out, static_cast<std::uint64_t>(wid - prev_n));
      }
      prev_n = wid;
    }
  }
  // Every vertex and every level entry must have been visited.
  return n_it == g.N.end() && c_it == g.C.end() && l_it == g.level.end();
}

void encode_generic(const Graph& g, std::string& out) {
  out.clear();
  out.push_back('\1');
  auto put_point = [&out](const Point& p) {
    put_varint(out, zigzag(p.x));
    put_varint(out, zigzag(p.y));
  };
  put_varint(out, g.N.size());
  for (const Point& p : g.N) put_point(p);
  put_varint(out, g.C.size());
  for (const Point& p : g.C) put_point(p);
  put_varint(out, g.level.size());
  for (const auto& [p, l] : g.level) {
    put_point(p);
    put_varint(out, zigzag(l));
  }
  put_varint(out, g.neighbors.size());
  for (const auto& [p, nbrs] : g.neighbors) {
    put_point(p);
    put_varint(out, nbrs.size());
    for (const Point& w : nbrs) put_point(w);
  }
}

void encode_into(const Graph& g, const Grid& grid, std::string& out) {
  if (!encode_compact(g, grid, out)) encode_generic(g, out);
}

Graph decode(const std::string& key, const LatticeSize& size, const Grid& grid) {
  Graph g;
  g.size = size;
  Reader r{key};
  const unsigned char format = r.byte();
  if (format == 0) {
    const std::uint64_t count = r.varint();
    std::int64_t prev = -1;
    for (std::uint64_t k = 0; k < count; ++k) {
      const std::int64_t id = prev + static_cast<std::int64_t>(r.varint());
      prev = id;
      const Point v = grid.point(id);
      const unsigned char tag = r.byte();
      if (tag == 0) {
        g.N.emplace_hint(g.N.end(), v);
      } else {
        g.C.emplace_hint(g.C.end(), v);
        g.level.emplace_hint(g.level.end(), v, tag - 1);
      }
      PointSet nbrs;
      const std::uint64_t n = r.varint();
      std::int64_t prev_n = 0;
      for (std::uint64_t m = 0; m < n; ++m) {
        const std::int64_t wid = m == 0 ? id + r.svarint() : prev_n + static_cast<std::int64_t>(r.varint());
        prev_n = wid;
        nbrs.emplace_hint(nbrs.end(), grid.point(wid));
      }
      g.neighbors.emplace_hint(g.neighbors.end(), v, std::move(nbrs));
    }
  } else if (format == 1) {
    for (std::uint64_t k = r.varint(); k > 0; --k) g.N.insert(r.point());
    for (std::uint64_t k = r.varint(); k > 0; --k) g.C.insert(r.point());
    for (std::uint64_t k = r.varint(); k > 0; --k) {
      const Point p = r.point();
      g.level[p] = static_cast<int>(r.svarint());
    }
    for (std::uint64_t k = r.varint(); k > 0; --k) {
      const Point p = r.point();
      PointSet& nbrs = g.neighbors[p];
      for (std::uint64_t m = r.varint(); m > 0; --m) nbrs.insert(r.point());
    }
  } else {
    throw std::invalid_argument("state key: unknown format");
  }
  if (r.pos != key.size()) throw std::invalid_argument("state key: trailing bytes");
  return g;
}

std::string point_text(const Point& p) { return to_string(p); }

// How a state was first reached: from state `parent` by one operation.
struct Origin {
  std::int64_t parent = -1;
  TraceCommand::Kind kind = TraceCommand::Kind::Check;
  Point at;
};

// What processing one state found. Workers fill these in parallel; the main
// thread merges them in state order, so the numbering of states, the counts
// and the first failure do not depend on the number of threads.
struct StateWork {
  std::vector<std::pair<std::string, Origin>> children;  // successors not seen before the batch
  std::int64_t refine_edges = 0, coarsen_edges = 0, ops_tried = 0, refused = 0, vertices = 0;
  bool failed = false;
  std::string message;              // the first failure in this state
  std::vector<TraceCommand> extra;  // the commands after the state that reproduce it
};

using RefineFn = std::function<RefineResult(Graph&, const Point&)>;
using CoarsenFn = std::function<CoarsenResult(Graph&, const Point&)>;

// Processes one state: checker, every operation on every vertex, inverses.
// Reads `seen` (no writes happen while workers run).
class StateProcessor {
 public:
  StateProcessor(const LatticeSize& size, const ExploreOptions& options, const Grid& grid, const RefineFn& refine,
                 const CoarsenFn& coarsen, const std::unordered_set<std::string_view>& seen)
      : size_(size), options_(options), grid_(grid), refine_(refine), coarsen_(coarsen), seen_(seen) {}

  void process(std::int64_t i, const std::string& key, StateWork& out) {
    out = StateWork{};
    out_ = &out;
    i_ = i;
    key_ = &key;
    g_ = decode(key, size_, grid_);
    out.vertices = static_cast<std::int64_t>(g_.N.size() + g_.C.size());

    if (options_.check_depth > 0) {
      if (const auto v = find_violation(g_, options_.check_depth)) {
        fail("invalid state: " + to_string(*v), {});
        return;  // never expand an invalid state
      }
    }

    std::vector<Point> vertices;
    vertices.reserve(g_.N.size() + g_.C.size());
    std::set_union(g_.N.begin(), g_.N.end(), g_.C.begin(), g_.C.end(), std::back_inserter(vertices));
    pending_.clear();
    for (const Point& v : vertices) {
      if (stop()) return;
      if (options_.try_every_op || g_.is_center(v)) try_op(TraceCommand::Kind::Refine, v);
      if (stop()) return;
      if (options_.try_every_op || g_.is_node(v)) try_op(TraceCommand::Kind::Coarsen, v);
    }
    if (!pending_.empty() && !stop()) {
      encode_into(g_, grid_, scratch_);
      if (scratch_ != *key_) fail_after_diagnosis("the state changed during refused operations", {});
    }
  }

 private:
  using Call = StepResult<Graph>;  // applied, or the refusal code

  static std::string op_text(TraceCommand::Kind kind, const Point& v) {
    return (kind == TraceCommand::Kind::Refine ? "refine " : "coarsen ") + point_text(v);
  }
  static TraceCommand::Kind inverse(TraceCommand::Kind kind) {
    return kind == TraceCommand::Kind::Refine ? TraceCommand::Kind::Coarsen : TraceCommand::Kind::Refine;
  }

  // Runs one operation on g_ with the operations under test; exceptions propagate.
  Call call(TraceCommand::Kind kind, const Point& v) {
    if (kind == TraceCommand::Kind::Refine) return {refine_(g_, v)};
    return {coarsen_(g_, v)};
  }

  bool stop() const { return options_.stop_at_first_failure && out_->failed; }

  void fail(std::string message, std::vector<TraceCommand> extra) {
    if (out_->failed) return;
    out_->failed = true;
    out_->message = std::move(message);
    out_->extra = std::move(extra);
  }

  // Refused calls are not compared with the state one by one (that would cost
  // an encoding each, most of the explorer's time). The graph is compared
  // once after every accepted operation's inverse and at the end of the
  // state, and any difference is first blamed on the refused calls since the
  // last comparison: they are replayed one at a time on a fresh copy, each
  // compared, and the first one that changes the state is reported.
  // Otherwise `message` is reported. Either way the graph is restored.
  void fail_after_diagnosis(std::string message, std::vector<TraceCommand> extra) {
    for (const auto& [kind, v] : pending_) {
      restore();
      Call c;
      try {
        c = call(kind, v);
      } catch (const std::exception&) {
        continue;  // not the refused call that changed the state
      }
      if (c.applied()) continue;  // it was refused on the original state only if it is refused here too
      encode_into(g_, grid_, scratch_);
      if (scratch_ != *key_) {
        message = op_text(kind, v) + " was refused (" + std::string(c.refusal()) + ") but changed the state";
        extra = {TraceCommand{kind, v, 0}};
        break;
      }
    }
    pending_.clear();
    fail(std::move(message), std::move(extra));
    restore();
  }

  void restore() { g_ = decode(*key_, size_, grid_); }

  // Runs op at v; if accepted, records the successor and undoes it with the
  // inverse operation, which must give back the state exactly.
  void try_op(TraceCommand::Kind kind, const Point& v) {
    ++out_->ops_tried;
    const TraceCommand cmd{kind, v, 0};
    Call r;
    try {
      r = call(kind, v);
    } catch (const std::exception& e) {
      return fail_after_diagnosis(op_text(kind, v) + " threw: " + e.what(), {cmd});
    }
    if (!r.applied()) {
      ++out_->refused;
      if (options_.try_every_op) pending_.emplace_back(kind, v);
      return;
    }
    if (kind == TraceCommand::Kind::Refine)
      ++out_->refine_edges;
    else
      ++out_->coarsen_edges;
    encode_into(g_, grid_, scratch_);
    if (seen_.count(std::string_view(scratch_)) == 0) out_->children.emplace_back(scratch_, Origin{i_, kind, v});

    const TraceCommand::Kind back_kind = inverse(kind);
    const TraceCommand back_cmd{back_kind, v, 0};
    const std::string pair = op_text(kind, v) + " then " + op_text(back_kind, v);
    Call back;
    try {
      back = call(back_kind, v);
    } catch (const std::exception& e) {
      return fail_after_diagnosis(op_text(back_kind, v) + " right after " + op_text(kind, v) + " threw: " + e.what(),
                                  {cmd, back_cmd});
    }
    if (!back.applied())
      return fail_after_diagnosis(pair + ": the " + (back_kind == TraceCommand::Kind::Refine ? "refine" : "coarsen") +
                                      " was refused (" + std::string(back.refusal()) + ")",
                                  {cmd, back_cmd});
    encode_into(g_, grid_, scratch_);
    if (scratch_ != *key_) return fail_after_diagnosis(pair + " does not restore the state", {cmd, back_cmd});
    pending_.clear();  // the state was intact before this operation
  }

  const LatticeSize& size_;
  const ExploreOptions& options_;
  const Grid& grid_;
  const RefineFn& refine_;
  const CoarsenFn& coarsen_;
  const std::unordered_set<std::string_view>& seen_;
  std::vector<std::pair<TraceCommand::Kind, Point>> pending_;  // refused calls not yet compared
  StateWork* out_ = nullptr;
  std::int64_t i_ = 0;
  const std::string* key_ = nullptr;
  Graph g_;
  std::string scratch_;
};

// States are processed in batches of kBatch consecutive indices; within a
// batch, in parallel; results are merged in index order.
constexpr std::int64_t kBatch = 256;

class Explorer {
 public:
  Explorer(const LatticeSize& size, const ExploreOptions& options) : size_(size), options_(options), grid_(size) {
    refine_ = options.refine ? options.refine : [](Graph& g, const Point& c) { return bccmis::refine(g, c); };
    coarsen_ = options.coarsen ? options.coarsen : [](Graph& g, const Point& n) { return bccmis::coarsen(g, n); };
    threads_ = options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
    threads_ = std::clamp(threads_, 1, 64);
  }

  ExploreResult run() {
    start_ = std::chrono::steady_clock::now();
    result_.size = size_;
    encode_into(make_lattice(size_), grid_, scratch_);
    add(scratch_, Origin{});
    std::int64_t next_progress = options_.progress_every;
    std::vector<StateWork> work(static_cast<std::size_t>(kBatch));
    std::vector<StateProcessor> processors;
    for (int t = 0; t < threads_; ++t) processors.emplace_back(size_, options_, grid_, refine_, coarsen_, seen_);

    while (result_.states < static_cast<std::int64_t>(keys_.size()) && !stopped()) {
      const std::int64_t begin = result_.states;
      std::int64_t end = std::min<std::int64_t>(begin + kBatch, static_cast<std::int64_t>(keys_.size()));
      if (options_.max_states > 0) end = std::min(end, options_.max_states);
      if (end <= begin) break;

      // Process [begin, end) on threads_ threads (this one included).
      std::atomic<std::int64_t> next{begin};
      auto worker = [&](StateProcessor& proc) {
        for (std::int64_t i = next++; i < end; i = next++)
          proc.process(i, keys_[static_cast<std::size_t>(i)], work[static_cast<std::size_t>(i - begin)]);
      };
      const int helpers = static_cast<int>(std::min<std::int64_t>(threads_, end - begin)) - 1;
      std::vector<std::thread> pool;
      for (int t = 0; t < helpers; ++t)
        pool.emplace_back(worker, std::ref(processors[static_cast<std::size_t>(t + 1)]));
      worker(processors[0]);
      for (std::thread& t : pool) t.join();

      // Merge in index order.
      for (std::int64_t i = begin; i < end && !stopped(); ++i) {
        StateWork& w = work[static_cast<std::size_t>(i - begin)];
        ++result_.states;
        result_.refine_edges += w.refine_edges;
        result_.coarsen_edges += w.coarsen_edges;
        result_.ops_tried += w.ops_tried;
        result_.refused += w.refused;
        result_.max_vertices = std::max(result_.max_vertices, w.vertices);
        for (auto& [key, origin] : w.children) add(key, origin);
        if (w.failed) {
          ++result_.failures;
          if (!result_.first_failure) result_.first_failure = ExploreFailure{w.message, trace_to(i, w.extra)};
        }
        w = StateWork{};
      }
      if (options_.progress && options_.progress_every > 0 && result_.states >= next_progress) {
        while (next_progress <= result_.states) next_progress += options_.progress_every;
        options_.progress(progress());
      }
      if (options_.max_states > 0 && result_.states >= options_.max_states) break;
    }
    result_.complete = !stopped() && result_.states == static_cast<std::int64_t>(keys_.size());
    result_.seconds = elapsed();
    if (options_.progress) options_.progress(progress());
    return result_;
  }

 private:
  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

  ExploreProgress progress() const {
    ExploreProgress p;
    p.states = result_.states;
    p.queued = static_cast<std::int64_t>(keys_.size()) - result_.states;
    p.refine_edges = result_.refine_edges;
    p.coarsen_edges = result_.coarsen_edges;
    p.ops_tried = result_.ops_tried;
    p.seconds = elapsed();
    return p;
  }

  bool stopped() const { return options_.stop_at_first_failure && result_.failures > 0; }

  void add(const std::string& key, const Origin& origin) {
    if (seen_.count(std::string_view(key)) != 0) return;
    keys_.push_back(key);
    seen_.insert(std::string_view(keys_.back()));
    origins_.push_back(origin);
    result_.key_bytes += static_cast<std::int64_t>(key.size());
  }

  // The trace from the initial lattice to state i, plus `extra` commands.
  std::string trace_to(std::int64_t i, const std::vector<TraceCommand>& extra) const {
    std::vector<TraceCommand> path;
    for (std::int64_t s = i; s >= 0 && origins_[static_cast<std::size_t>(s)].parent >= 0;
         s = origins_[static_cast<std::size_t>(s)].parent) {
      const Origin& o = origins_[static_cast<std::size_t>(s)];
      path.push_back(TraceCommand{o.kind, o.at, 0});
    }
    Trace t;
    t.size = size_;
    t.commands.assign(path.rbegin(), path.rend());
    t.commands.insert(t.commands.end(), extra.begin(), extra.end());
    return format_trace(t);
  }

  LatticeSize size_;
  const ExploreOptions& options_;
  Grid grid_;
  RefineFn refine_;
  CoarsenFn coarsen_;
  int threads_ = 1;
  std::chrono::steady_clock::time_point start_;
  ExploreResult result_;
  std::deque<std::string> keys_;  // state i's key; elements never move
  std::vector<Origin> origins_;   // how state i was first reached
  std::unordered_set<std::string_view> seen_;
  std::string scratch_;
};

}  // namespace

std::string encode_state_key(const Graph& g) {
  std::string out;
  encode_into(g, Grid(g.size), out);
  return out;
}

Graph decode_state_key(const std::string& key, const LatticeSize& size) { return decode(key, size, Grid(size)); }

ExploreResult explore(const LatticeSize& size, const ExploreOptions& options) {
  validate_lattice_size(size);
  return Explorer(size, options).run();
}

std::string summary(const ExploreResult& r) {
  char secs[32];
  std::snprintf(secs, sizeof secs, "%.2f", r.seconds);
  std::string out = "explore " + std::to_string(r.size.W) + " " + std::to_string(r.size.H) + " " +
                    std::to_string(r.size.L) + ": " + std::to_string(r.states) + " states, " +
                    std::to_string(r.refine_edges) + " refine edges, " + std::to_string(r.coarsen_edges) +
                    " coarsen edges, " + std::to_string(r.ops_tried) + " ops tried, ";
  if (r.first_failure)
    out += "FAILED (" + std::to_string(r.failures) + " failure" + (r.failures == 1 ? "" : "s") +
           "): " + r.first_failure->message;
  else if (!r.complete)
    out += "incomplete";
  else
    out += "ok";
  return out + " (" + secs + " s)";
}

std::string to_json(const ExploreResult& r) {
  char secs[32];
  std::snprintf(secs, sizeof secs, "%.3f", r.seconds);
  std::string out =
      "{\"W\": " + std::to_string(r.size.W) + ", \"H\": " + std::to_string(r.size.H) +
      ", \"L\": " + std::to_string(r.size.L) + ", \"states\": " + std::to_string(r.states) +
      ", \"refine_edges\": " + std::to_string(r.refine_edges) +
      ", \"coarsen_edges\": " + std::to_string(r.coarsen_edges) + ", \"ops_tried\": " + std::to_string(r.ops_tried) +
      ", \"refused\": " + std::to_string(r.refused) + ", \"failures\": " + std::to_string(r.failures) +
      ", \"max_vertices\": " + std::to_string(r.max_vertices) + ", \"complete\": " + (r.complete ? "true" : "false") +
      ", \"ok\": " + (r.ok() ? "true" : "false") + ", \"seconds\": " + secs;
  if (r.first_failure)
    out += ", \"failure\": {\"message\": " + json_string(r.first_failure->message) +
           ", \"trace\": " + json_string(r.first_failure->trace) + "}";
  else
    out += ", \"failure\": null";
  return out + "}";
}

}  // namespace bccmis
