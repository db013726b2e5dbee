// The explorer of bccmis/explore/explore.h, written once for every lattice
// with the data layout of the reference graphs (Graph in 2D, d3::Graph in
// 3D: N, C, neighbors, level, size). What differs between the dimensions is
// given by ExploreTraits<G>, specialised beside each instantiation
// (explore.cpp, d3/explore.cpp):
//
//   static constexpr int dimension;
//   static coordinates(p) -> std::array<std::int64_t, dimension>
//   static point(coordinates) -> the point type
//   static extents(size)      -> the domain's extent along each axis
//   static size_fields(size)  -> the lattice line's numbers with their names
//   static violation(g, depth) -> the checker's first complaint, if any
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <exception>
#include <functional>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <unordered_set>
#include <utility>
#include <vector>

#include "bccmis/explore/explore.h"
#include "bccmis/io/format.h"
#include "bccmis/json_writer.h"
#include "bccmis/lattice.h"
#include "bccmis/trace.h"

namespace bccmis::explore_detail {

template <class G>
struct ExploreTraits;

// ---- The exact state key ----------------------------------------------------
//
// Two encodings, told apart by the first byte:
//
//  0 (compact): used when the graph is "regular": every point (vertex or
//    neighbor) lies on the integer grid [0, extent] along every axis, N and C
//    are disjoint, the keys of `neighbors` are exactly N ∪ C, the keys of
//    `level` are exactly C, and every level is in 0..200. Points are numbered
//    in mixed radix, id = x * (H*S + 1) + y in 2D and
//    id = (x * (H*S + 1) + y) * (D*S + 1) + z in 3D, which is increasing in
//    the (x, y[, z]) order of the point type. Then, for each entry of
//    `neighbors` in order:
//      varint(id - previous id)          (previous id starts at -1)
//      byte 0 for a node, 1 + level for a center
//      varint(|N(v)|)
//      zigzag varint(first neighbor id - id), varint(delta) for the others
//  1 (generic): anything else, every container written out with zigzag
//    varints of raw coordinates.
// Both are decodable, so the key is exact.

inline void put_varint(std::string& out, std::uint64_t v) {
  while (v >= 0x80) {
    out.push_back(static_cast<char>((v & 0x7f) | 0x80));
    v >>= 7;
  }
  out.push_back(static_cast<char>(v));
}

inline std::uint64_t zigzag(std::int64_t v) {
  return (static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63);
}

inline std::int64_t unzigzag(std::uint64_t v) {
  return static_cast<std::int64_t>(v >> 1) ^ -static_cast<std::int64_t>(v & 1);
}

template <class G>
using point_of = point_type_t<G>;
template <class G>
using size_of_t = typename G::size_type;
template <class G>
using coords_t = std::array<std::int64_t, ExploreTraits<G>::dimension>;

template <class G>
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
  point_of<G> point() {
    coords_t<G> c{};
    for (std::int64_t& v : c) v = svarint();
    return ExploreTraits<G>::point(c);
  }
};

template <class G>
struct Grid {
  coords_t<G> max{};  // the extent along each axis
  explicit Grid(const size_of_t<G>& size) : max(ExploreTraits<G>::extents(size)) {}
  bool contains(const point_of<G>& p) const {
    const coords_t<G> c = ExploreTraits<G>::coordinates(p);
    for (std::size_t k = 0; k < c.size(); ++k)
      if (c[k] < 0 || c[k] > max[k]) return false;
    return true;
  }
  std::int64_t id(const point_of<G>& p) const {
    const coords_t<G> c = ExploreTraits<G>::coordinates(p);
    std::int64_t id = c[0];
    for (std::size_t k = 1; k < c.size(); ++k) id = id * (max[k] + 1) + c[k];
    return id;
  }
  point_of<G> point(std::int64_t id) const {
    coords_t<G> c{};
    for (std::size_t k = c.size(); k-- > 1;) {
      c[k] = id % (max[k] + 1);
      id /= max[k] + 1;
    }
    c[0] = id;
    return ExploreTraits<G>::point(c);
  }
};

template <class G>
bool encode_compact(const G& g, const Grid<G>& grid, std::string& out) {
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
    for (const auto& w : nbrs) {
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

template <class G>
void encode_generic(const G& g, std::string& out) {
  out.clear();
  out.push_back('\1');
  auto put_point = [&out](const point_of<G>& p) {
    for (const std::int64_t v : ExploreTraits<G>::coordinates(p)) put_varint(out, zigzag(v));
  };
  put_varint(out, g.N.size());
  for (const auto& p : g.N) put_point(p);
  put_varint(out, g.C.size());
  for (const auto& p : g.C) put_point(p);
  put_varint(out, g.level.size());
  for (const auto& [p, l] : g.level) {
    put_point(p);
    put_varint(out, zigzag(l));
  }
  put_varint(out, g.neighbors.size());
  for (const auto& [p, nbrs] : g.neighbors) {
    put_point(p);
    put_varint(out, nbrs.size());
    for (const auto& w : nbrs) put_point(w);
  }
}

template <class G>
void encode_into(const G& g, const Grid<G>& grid, std::string& out) {
  if (!encode_compact(g, grid, out)) encode_generic(g, out);
}

template <class G>
G decode(const std::string& key, const size_of_t<G>& size, const Grid<G>& grid) {
  using PointSet = std::remove_cvref_t<decltype(G{}.N)>;
  G g;
  g.size = size;
  Reader<G> r{key};
  const unsigned char format = r.byte();
  if (format == 0) {
    const std::uint64_t count = r.varint();
    std::int64_t prev = -1;
    for (std::uint64_t k = 0; k < count; ++k) {
      const std::int64_t id = prev + static_cast<std::int64_t>(r.varint());
      prev = id;
      const point_of<G> v = grid.point(id);
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
      const point_of<G> p = r.point();
      g.level[p] = static_cast<int>(r.svarint());
    }
    for (std::uint64_t k = r.varint(); k > 0; --k) {
      const point_of<G> p = r.point();
      PointSet& nbrs = g.neighbors[p];
      for (std::uint64_t m = r.varint(); m > 0; --m) nbrs.insert(r.point());
    }
  } else {
    throw std::invalid_argument("state key: unknown format");
  }
  if (r.pos != key.size()) throw std::invalid_argument("state key: trailing bytes");
  return g;
}

// How a state was first reached: from state `parent` by one operation.
template <class G>
struct Origin {
  std::int64_t parent = -1;
  CommandKind kind = CommandKind::Check;
  point_of<G> at;
};

// What processing one state found. Workers fill these in parallel; the main
// thread merges them in state order, so the numbering of states, the counts
// and the first failure do not depend on the number of threads.
template <class G>
struct StateWork {
  std::vector<std::pair<std::string, Origin<G>>> children;  // successors not seen before the batch
  std::int64_t refine_edges = 0, coarsen_edges = 0, ops_tried = 0, refused = 0, vertices = 0;
  bool failed = false;
  std::string message;                    // the first failure in this state
  std::vector<trace_command_t<G>> extra;  // the commands after the state that reproduce it
};

template <class G>
using RefineFn = std::function<refine_result_t<G>(G&, const point_of<G>&)>;
template <class G>
using CoarsenFn = std::function<coarsen_result_t<G>(G&, const point_of<G>&)>;

// Processes one state: checker, every operation on every vertex, inverses.
// Reads `seen` (no writes happen while workers run).
template <class G>
class StateProcessor {
 public:
  using Point = point_of<G>;
  using Size = size_of_t<G>;
  using Command = trace_command_t<G>;

  StateProcessor(const Size& size, const BasicExploreOptions<G>& options, const Grid<G>& grid,
                 const RefineFn<G>& refine, const CoarsenFn<G>& coarsen,
                 const std::unordered_set<std::string_view>& seen)
      : size_(size), options_(options), grid_(grid), refine_(refine), coarsen_(coarsen), seen_(seen) {}

  void process(std::int64_t i, const std::string& key, StateWork<G>& out) {
    out = StateWork<G>{};
    out_ = &out;
    i_ = i;
    key_ = &key;
    g_ = decode(key, size_, grid_);
    out.vertices = static_cast<std::int64_t>(g_.N.size() + g_.C.size());

    if (options_.check_depth > 0) {
      std::optional<std::string> v;
      try {
        v = ExploreTraits<G>::violation(g_, options_.check_depth);
      } catch (const std::exception& e) {
        v = std::string("the checker threw: ") + e.what();
      }
      if (v) {
        fail("invalid state: " + *v, {});
        return;  // never expand an invalid state
      }
    }

    std::vector<Point> vertices;
    vertices.reserve(g_.N.size() + g_.C.size());
    std::set_union(g_.N.begin(), g_.N.end(), g_.C.begin(), g_.C.end(), std::back_inserter(vertices));
    pending_.clear();
    for (const Point& v : vertices) {
      if (stop()) return;
      if (options_.try_every_op || g_.is_center(v)) try_op(CommandKind::Refine, v);
      if (stop()) return;
      if (options_.try_every_op || g_.is_node(v)) try_op(CommandKind::Coarsen, v);
    }
    if (!pending_.empty() && !stop()) {
      encode_into(g_, grid_, scratch_);
      if (scratch_ != *key_) fail_after_diagnosis("the state changed during refused operations", {});
    }
  }

 private:
  using Call = StepResult<G>;  // applied, or the refusal code

  static std::string op_text(CommandKind kind, const Point& v) {
    return (kind == CommandKind::Refine ? "refine " : "coarsen ") + to_string(v);
  }
  static CommandKind inverse(CommandKind kind) {
    return kind == CommandKind::Refine ? CommandKind::Coarsen : CommandKind::Refine;
  }

  // Runs one operation on g_ with the operations under test; exceptions propagate.
  Call call(CommandKind kind, const Point& v) {
    if (kind == CommandKind::Refine) return {refine_(g_, v)};
    return {coarsen_(g_, v)};
  }

  bool stop() const { return options_.stop_at_first_failure && out_->failed; }

  void fail(std::string message, std::vector<Command> extra) {
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
  void fail_after_diagnosis(std::string message, std::vector<Command> extra) {
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
        extra = {Command{kind, v, 0}};
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
  void try_op(CommandKind kind, const Point& v) {
    ++out_->ops_tried;
    const Command cmd{kind, v, 0};
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
    if (kind == CommandKind::Refine)
      ++out_->refine_edges;
    else
      ++out_->coarsen_edges;
    encode_into(g_, grid_, scratch_);
    if (seen_.count(std::string_view(scratch_)) == 0) out_->children.emplace_back(scratch_, Origin<G>{i_, kind, v});

    const CommandKind back_kind = inverse(kind);
    const Command back_cmd{back_kind, v, 0};
    const std::string pair = op_text(kind, v) + " then " + op_text(back_kind, v);
    Call back;
    try {
      back = call(back_kind, v);
    } catch (const std::exception& e) {
      return fail_after_diagnosis(op_text(back_kind, v) + " right after " + op_text(kind, v) + " threw: " + e.what(),
                                  {cmd, back_cmd});
    }
    if (!back.applied())
      return fail_after_diagnosis(pair + ": the " + (back_kind == CommandKind::Refine ? "refine" : "coarsen") +
                                      " was refused (" + std::string(back.refusal()) + ")",
                                  {cmd, back_cmd});
    encode_into(g_, grid_, scratch_);
    if (scratch_ != *key_) return fail_after_diagnosis(pair + " does not restore the state", {cmd, back_cmd});
    pending_.clear();  // the state was intact before this operation
  }

  const Size& size_;
  const BasicExploreOptions<G>& options_;
  const Grid<G>& grid_;
  const RefineFn<G>& refine_;
  const CoarsenFn<G>& coarsen_;
  const std::unordered_set<std::string_view>& seen_;
  std::vector<std::pair<CommandKind, Point>> pending_;  // refused calls not yet compared
  StateWork<G>* out_ = nullptr;
  std::int64_t i_ = 0;
  const std::string* key_ = nullptr;
  G g_;
  std::string scratch_;
};

// States are processed in batches of kBatch consecutive indices; within a
// batch, in parallel; results are merged in index order.
constexpr std::int64_t kBatch = 256;

template <class G>
class Explorer {
 public:
  using Size = size_of_t<G>;
  using Result = BasicExploreResult<Size>;

  Explorer(const Size& size, const BasicExploreOptions<G>& options) : size_(size), options_(options), grid_(size) {
    refine_ = options.refine ? options.refine : [](G& g, const point_of<G>& c) { return refine(g, c); };
    coarsen_ = options.coarsen ? options.coarsen : [](G& g, const point_of<G>& n) { return coarsen(g, n); };
    threads_ = options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
    threads_ = std::clamp(threads_, 1, 64);
  }

  Result run() {
    start_ = std::chrono::steady_clock::now();
    result_.size = size_;
    encode_into(G(size_), grid_, scratch_);
    add(scratch_, Origin<G>{});
    std::int64_t next_progress = options_.progress_every;
    std::vector<StateWork<G>> work(static_cast<std::size_t>(kBatch));
    std::vector<StateProcessor<G>> processors;
    for (int t = 0; t < threads_; ++t) processors.emplace_back(size_, options_, grid_, refine_, coarsen_, seen_);

    while (result_.states < static_cast<std::int64_t>(keys_.size()) && !stopped()) {
      const std::int64_t begin = result_.states;
      std::int64_t end = std::min<std::int64_t>(begin + kBatch, static_cast<std::int64_t>(keys_.size()));
      if (options_.max_states > 0) end = std::min(end, options_.max_states);
      if (end <= begin) break;

      // Process [begin, end) on threads_ threads (this one included).
      std::atomic<std::int64_t> next{begin};
      auto worker = [&](StateProcessor<G>& proc) {
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
        StateWork<G>& w = work[static_cast<std::size_t>(i - begin)];
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
        w = StateWork<G>{};
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

  void add(const std::string& key, const Origin<G>& origin) {
    if (seen_.count(std::string_view(key)) != 0) return;
    keys_.push_back(key);
    seen_.insert(std::string_view(keys_.back()));
    origins_.push_back(origin);
    result_.key_bytes += static_cast<std::int64_t>(key.size());
  }

  // The trace from the initial lattice to state i, plus `extra` commands.
  std::string trace_to(std::int64_t i, const std::vector<trace_command_t<G>>& extra) const {
    std::vector<trace_command_t<G>> path;
    for (std::int64_t s = i; s >= 0 && origins_[static_cast<std::size_t>(s)].parent >= 0;
         s = origins_[static_cast<std::size_t>(s)].parent) {
      const Origin<G>& o = origins_[static_cast<std::size_t>(s)];
      path.push_back(trace_command_t<G>{o.kind, o.at, 0});
    }
    BasicTrace<point_of<G>, Size> t;
    t.size = size_;
    t.commands.assign(path.rbegin(), path.rend());
    t.commands.insert(t.commands.end(), extra.begin(), extra.end());
    return format_trace(t);
  }

  Size size_;
  const BasicExploreOptions<G>& options_;
  Grid<G> grid_;
  RefineFn<G> refine_;
  CoarsenFn<G> coarsen_;
  int threads_ = 1;
  std::chrono::steady_clock::time_point start_;
  Result result_;
  std::deque<std::string> keys_;    // state i's key; elements never move
  std::vector<Origin<G>> origins_;  // how state i was first reached
  std::unordered_set<std::string_view> seen_;
  std::string scratch_;
};

template <class G>
std::string encode_key(const G& g) {
  std::string out;
  encode_into(g, Grid<G>(g.size), out);
  return out;
}

template <class G>
G decode_key(const std::string& key, const size_of_t<G>& size) {
  return decode(key, size, Grid<G>(size));
}

// ---- Reports ------------------------------------------------------------------

template <class G>
std::string summary_of(const BasicExploreResult<size_of_t<G>>& r) {
  char secs[32];
  std::snprintf(secs, sizeof secs, "%.2f", r.seconds);
  std::string out = "explore";
  for (const auto& [name, value] : ExploreTraits<G>::size_fields(r.size)) out += " " + std::to_string(value);
  out += ": " + std::to_string(r.states) + " states, " + std::to_string(r.refine_edges) + " refine edges, " +
         std::to_string(r.coarsen_edges) + " coarsen edges, " + std::to_string(r.ops_tried) + " ops tried, ";
  if (r.first_failure)
    out += "FAILED (" + std::to_string(r.failures) + " failure" + (r.failures == 1 ? "" : "s") +
           "): " + r.first_failure->message;
  else if (!r.complete)
    out += "incomplete";
  else
    out += "ok";
  return out + " (" + secs + " s)";
}

template <class G>
std::string json_of(const BasicExploreResult<size_of_t<G>>& r) {
  char secs[32];
  std::snprintf(secs, sizeof secs, "%.3f", r.seconds);
  JsonWriter out;
  out.begin_object();
  for (const auto& [name, value] : ExploreTraits<G>::size_fields(r.size)) out.member(name, value);
  out.member("states", r.states)
      .member("refine_edges", r.refine_edges)
      .member("coarsen_edges", r.coarsen_edges)
      .member("ops_tried", r.ops_tried)
      .member("refused", r.refused)
      .member("failures", r.failures)
      .member("max_vertices", r.max_vertices)
      .member("complete", r.complete)
      .member("ok", r.ok())
      .key("seconds")
      .json_value(secs)
      .key("failure");
  if (r.first_failure)
    out.begin_object().member("message", r.first_failure->message).member("trace", r.first_failure->trace).end_object();
  else
    out.null();
  return out.end_object().str();
}

}  // namespace bccmis::explore_detail
