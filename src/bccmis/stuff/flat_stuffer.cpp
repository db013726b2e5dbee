// The flat stuffer: S5-S9 of spec/stuffing.md with the same decisions in
// the same order as the reference stuffer (reference_stuffer.cpp), on arrays
// indexed by the lattice vertices numbered in position order. stuff() on a
// d3::fast::Lattice and stuff_part() (S16).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "bccmis/d3/detail/position_order.h"
#include "bccmis/d3/point.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/stuff/detail/leaf_blocks.h"
#include "bccmis/stuff/detail/parallel_ranges.h"
#include "bccmis/stuff/detail/stencils.h"
#include "bccmis/stuff/detail/stuffer.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

namespace {

/// A vertex of the output (S8's key) on the lattice vertices numbered in
/// position order: lattice vertex i is (i, i), the cut point on lattice edge
/// ij is (min(i, j), max(i, j)), packed as high << 32 | low. The numbering
/// keeps the order of positions, so the packed keys sort as S8's pairs of
/// points.
using VKey = std::uint64_t;
std::uint32_t first(VKey k) { return static_cast<std::uint32_t>(k >> 32); }
std::uint32_t second(VKey k) { return static_cast<std::uint32_t>(k); }
bool is_cut(VKey k) { return first(k) != second(k); }

/// Cut edge -> cut index: open addressing on the packed edge key (linear
/// probing, no deletion).
class EdgeTable {
 public:
  void reserve(std::size_t n) {
    std::size_t slots = 16;
    while (slots < 2 * n) slots *= 2;
    keys_.assign(slots, kEmpty);
    values_.assign(slots, 0);
    used_ = 0;
  }
  /// The value at k, or kNone.
  std::uint32_t find(VKey k) const {
    for (std::size_t i = hash(k);; i = (i + 1) & (keys_.size() - 1)) {
      if (keys_[i] == k) return values_[i];
      if (keys_[i] == kEmpty) return kNone;
    }
  }
  /// Inserts k -> v; k must be absent.
  void insert(VKey k, std::uint32_t v) {
    if (2 * (used_ + 1) > keys_.size()) grow();
    std::size_t i = hash(k);
    while (keys_[i] != kEmpty) i = (i + 1) & (keys_.size() - 1);
    keys_[i] = k;
    values_[i] = v;
    ++used_;
  }
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

 private:
  static constexpr VKey kEmpty = ~VKey{0};  // never an edge: its ends differ
  std::size_t hash(VKey k) const {
    return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> 17) & (keys_.size() - 1);
  }
  void grow() {
    std::vector<VKey> keys = std::move(keys_);
    std::vector<std::uint32_t> values = std::move(values_);
    reserve(keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i] != kEmpty) insert(keys[i], values[i]);
  }
  std::vector<VKey> keys_;
  std::vector<std::uint32_t> values_;
  std::size_t used_ = 0;
};

/// Below this many vertices or cut points a thread is not worth starting.
inline constexpr std::size_t kLeastPerThread = 256;

/// S5-S9 on the graded mesh of a lattice G (d3::Graph or d3::fast::Lattice,
/// through the vocabulary: is_center, level_of). The lattice's vertices are
/// numbered in position order and every per-vertex datum is an array.
template <class G>
class Stuffer {
 public:
  Stuffer(const Shape& shape, const Fit& fit, const G& g, const StuffOptions& options)
      : shape_(shape), fit_(fit), g_(g), options_(options) {}

  /// Also report, for stuff_part(), each output vertex's key as lattice
  /// points and where each lattice tetrahedron's output tetrahedra begin.
  void record(std::vector<std::array<d3::Point, 2>>* keys, std::vector<std::uint32_t>* begin) {
    keys_ = keys;
    begin_ = begin;
  }

  /// Call `release` once the lattice is no longer asked (M26: after S6, the
  /// levels of every leaf read first); the stuffer asks it nothing after.
  void release_after_warp(std::function<void()> release) { release_ = std::move(release); }

  /// S5-S9 on every tetrahedron of the graded mesh of g, extracted leaf by
  /// leaf in blocks (`threads` at a time) and numbered as they come: no
  /// array of the lattice's tetrahedra.
  Stuffed run_whole(int threads, PhaseTimes* times) {
    detail::PhaseClock clock(times);
    begin_numbering(2 * cell_count(g_) + node_count(g_));
    {
      // S28b: on more than one thread each block is numbered on its own where
      // it is extracted, then merged into the one table in block order; on
      // one, numbered into the one table at once (the same ids, S28b). The
      // blocks' tables and lists are freed here, not kept through S5-S9 (S28d).
      std::vector<Numbering> blocks(static_cast<std::size_t>(detail::thread_count(threads)));
      if (blocks.size() == 1)
        detail::for_each_block(
            g_, threads, [](std::size_t, std::span<const d3::Tet>) {},
            [this](std::size_t, std::span<const d3::Tet> block) { number(block); });
      else
        detail::for_each_block(
            g_, threads,
            [&blocks](std::size_t slot, std::span<const d3::Tet> block) { number_block(block, blocks[slot]); },
            [this, &blocks](std::size_t slot, std::span<const d3::Tet>) { merge(blocks[slot]); });
    }
    end_numbering();
    clock.lap(&PhaseTimes::mesh);
    return stuff(times);
  }

  /// S5-S9 on the tetrahedra `tets` of the graded mesh of g.
  Stuffed run(std::span<const d3::Tet> tets, PhaseTimes* times) {
    begin_numbering(std::min(2 * cell_count(g_) + node_count(g_), 4 * tets.size()));
    number(tets);
    end_numbering();
    return stuff(times);
  }

 private:
  Stuffed stuff(PhaseTimes* times) {
    detail::PhaseClock clock(times);
    out_.lattice_tetrahedra = ids_.size();
    evaluate();
    cut();
    clock.lap(&PhaseTimes::cut);
    warp();
    if (release_) {  // M26.2: every leaf's level read, then the lattice freed
      level_.assign(points_.size(), -1);
      for (const Ids& t : ids_)
        if (level_[t[0]] < 0) level_[t[0]] = level_of(g_, points_[t[0]]);
      release_();
      released_ = true;
    }
    clock.lap(&PhaseTimes::warp);
    fill();
    Stuffed s = finish();
    clock.lap(&PhaseTimes::stencils);
    return s;
  }

  using Ids = std::array<std::uint32_t, 4>;

  /// S7-S9 on a range of the lattice tetrahedra, into the range's own output
  /// (S28a): it reads the stuffer's vertices, values, positions and cut
  /// points, all fixed after S6, and writes only its own.
  class Range : public detail::Stencils<Range, std::uint32_t, VKey, std::uint32_t> {
    using Base = detail::Stencils<Range, std::uint32_t, VKey, std::uint32_t>;

   public:
    explicit Range(const Stuffer& s) : s_(s) {}
    /// The stencils of lattice tetrahedra [b, e); with `begin`, where each
    /// one's output tetrahedra begin in this range's output.
    void fill(std::size_t b, std::size_t e, std::vector<std::uint32_t>* begin) {
      for (std::size_t ti = b; ti < e; ++ti) {
        if (begin) begin->push_back(static_cast<std::uint32_t>(this->tets_out_.size()));
        const Ids& t = s_.ids_[ti];
        bool warped = false;
        for (const std::uint32_t p : t) warped = warped || s_.warped_[p];
        if (warped) detail::check_regular(s_.lattice_tet(ti), s_.fit_.size.L);
        Base::fill(t, [this, &t] { return level(t[0]); });
      }
    }
    std::vector<std::array<std::uint32_t, 4>>& tets() { return this->tets_out_; }
    std::vector<int>& levels() { return this->levels_out_; }

   private:
    friend Base;
    // What the stencils (detail/stencils.h) ask of a stuffer.
    static VKey lattice_key(std::uint32_t i) { return Stuffer::lattice_key(i); }
    static VKey cut_key(std::uint32_t i, std::uint32_t j) { return Stuffer::cut_key(i, j); }
    std::int64_t length2(std::uint32_t i, std::uint32_t j) const { return s_.length2(i, j); }
    d3::Point point_of(VKey k) const { return s_.points_[first(k)]; }
    double value(std::uint32_t i) const { return s_.value_[i]; }
    Vec3 pos(VKey k) const { return s_.pos(k); }
    std::uint32_t store(VKey k) const { return s_.store(k); }
    Vec3 stored_pos(std::uint32_t x) const { return s_.stored_pos(x); }
    bool flat_allowed() const { return static_cast<bool>(s_.options_.place_cut); }

    /// The level of leaf `leaf` (a lattice tetrahedron's vertex 0,
    /// spec/mesh3d.md), asked of the lattice once per run of tetrahedra of
    /// one leaf (S28a).
    int level(std::uint32_t leaf) {
      if (leaf != leaf_) leaf_ = leaf, level_ = s_.leaf_level(leaf);
      return level_;
    }

    const Stuffer& s_;
    std::uint32_t leaf_ = EdgeTable::kNone;
    int level_ = -1;
  };

  // The keys and positions of S8 on the numbered vertices.
  static VKey lattice_key(std::uint32_t i) { return (VKey{i} << 32) | i; }
  static VKey cut_key(std::uint32_t i, std::uint32_t j) { return i < j ? (VKey{i} << 32) | j : (VKey{j} << 32) | i; }
  std::int64_t length2(std::uint32_t i, std::uint32_t j) const { return detail::length2(points_[i], points_[j]); }
  Vec3 pos(VKey k) const { return is_cut(k) ? cuts_[cut_index_.find(k)].pos : pos_[first(k)]; }
  // An output vertex as the stencils keep it: lattice vertex i as i, cut
  // point c as points_.size() + c (16 bytes an output tetrahedron, renumbered
  // in place by finish()).
  std::uint32_t store(VKey k) const {
    return is_cut(k) ? static_cast<std::uint32_t>(points_.size()) + cut_index_.find(k) : first(k);
  }
  Vec3 stored_pos(std::uint32_t x) const { return x < points_.size() ? pos_[x] : cuts_[x - points_.size()].pos; }

  // The lattice vertices of the mesh in position order, the tetrahedra on
  // them: ids in order of first use through a hash table (the one position
  // table), then renumbered by rank of position.
  void begin_numbering(std::size_t most) {
    // The vertices are centers, nodes and hull points (centers of the
    // domain's faces, at most one per leaf): load at most 1/2.
    std::size_t slots = 16;
    while (slots < 2 * most) slots *= 2;
    table_.assign(slots, EdgeTable::kNone);
  }
  /// Vertices numbered in order of first use through a table of positions.
  struct Numbering {
    std::vector<std::uint32_t> table;      ///< points by hash of position
    std::vector<std::size_t> used;         ///< the table's slots in use (a block's, to clear)
    std::vector<d3::Point> points;         ///< in order of first use
    std::vector<Ids> ids;                  ///< the tetrahedra on points
    std::vector<std::uint32_t> to_global;  ///< points -> the stuffer's ids (merge)
  };
  /// S28b: the block `tets` numbered on its own into b (its previous
  /// contents dropped).
  static void number_block(std::span<const d3::Tet> tets, Numbering& b) {
    for (const std::size_t k : b.used) b.table[k] = EdgeTable::kNone;
    b.used.clear();
    b.points.clear();
    b.ids.clear();
    std::size_t slots = 16;
    while (slots < 8 * tets.size()) slots *= 2;  // at most 4 new points a tetrahedron: load at most 1/2
    if (b.table.size() < slots) b.table.assign(slots, EdgeTable::kNone);
    number(tets, b.table, b.points, b.ids, &b.used);
  }
  /// S28b: block b's points given the stuffer's ids in their order, its
  /// tetrahedra appended on them.
  void merge(Numbering& b) {
    const std::size_t mask = table_.size() - 1;
    b.to_global.resize(b.points.size());
    for (std::size_t i = 0; i < b.points.size(); ++i) {
      const d3::Point& p = b.points[i];
      std::size_t k = d3::PointHash{}(p)&mask;
      while (table_[k] != EdgeTable::kNone && !(points_[table_[k]] == p)) k = (k + 1) & mask;
      if (table_[k] == EdgeTable::kNone) {
        table_[k] = static_cast<std::uint32_t>(points_.size());
        points_.push_back(p);
      }
      b.to_global[i] = table_[k];
    }
    for (const Ids& t : b.ids)
      ids_.push_back({b.to_global[t[0]], b.to_global[t[1]], b.to_global[t[2]], b.to_global[t[3]]});
  }
  void number(std::span<const d3::Tet> tets) { number(tets, table_, points_, ids_, nullptr); }
  /// tets numbered in order of first use through `table` into points and
  /// ids (appended); the slots taken listed in `used` when given.
  static void number(std::span<const d3::Tet> tets, std::vector<std::uint32_t>& table, std::vector<d3::Point>& points,
                     std::vector<Ids>& ids, std::vector<std::size_t>* used) {
    const std::size_t mask = table.size() - 1;
    const auto hash = [&](const d3::Point& p) { return d3::PointHash{}(p)&mask; };
    // A leaf's tetrahedra come together, all with the leaf as vertex 0 and
    // a face's with its apex as vertex 1 (spec/mesh3d.md M24): those two are
    // most often the previous tetrahedron's, numbered already.
    const d3::Tet* previous = nullptr;
    for (const d3::Tet& t : tets) {
      Ids t_ids{};
      for (std::size_t i = 0; i < 4; ++i) {
        if (i < 2 && previous && (*previous)[i] == t[i]) {
          t_ids[i] = ids.back()[i];
          continue;
        }
        std::size_t k = hash(t[i]);
        while (table[k] != EdgeTable::kNone && !(points[table[k]] == t[i])) k = (k + 1) & mask;
        if (table[k] == EdgeTable::kNone) {
          table[k] = static_cast<std::uint32_t>(points.size());
          points.push_back(t[i]);
          if (used) used->push_back(k);
        }
        t_ids[i] = table[k];
      }
      ids.push_back(t_ids);
      previous = &t;
    }
  }
  void end_numbering() {
    std::vector<std::uint32_t>().swap(table_);  // M26: its memory, not only its size
    // S8a: the rank of each point by position, by a radix sort.
    const std::vector<std::uint32_t> order = d3::detail::position_order(points_);
    std::vector<std::uint32_t> rank(points_.size());
    std::vector<d3::Point> sorted(points_.size());
    for (std::uint32_t r = 0; r < order.size(); ++r) rank[order[r]] = r, sorted[r] = points_[order[r]];
    points_ = std::move(sorted);
    // S28a: each tetrahedron's ids on their own, so over ranges.
    detail::for_each_range(ids_.size(), options_.threads, kLeastPerThread, [this, &rank](std::size_t b, std::size_t e) {
      for (std::size_t ti = b; ti < e; ++ti)
        for (std::uint32_t& i : ids_[ti]) i = rank[i];
    });
  }

  // S28: each vertex on its own, so on `threads` threads.
  void evaluate() {
    value_.resize(points_.size());
    pos_.resize(points_.size());
    detail::for_each_range(points_.size(), options_.threads, kLeastPerThread, [this](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) {
        pos_[i] = fit_.to_space(points_[i]);
        const int side = shape_.side(pos_[i]);  // S5: only the sign enters
        value_[i] = static_cast<std::int8_t>((side > 0) - (side < 0));
      }
    });
  }

  // S5
  void cut() {
    // S28a: each range lists its cut edges at their first use in the range;
    // the lists joined in range order, each edge kept at its first use.
    using Edges = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
    std::vector<Edges> listed(detail::part_count(ids_.size(), options_.threads, kLeastPerThread));
    detail::for_each_part(ids_.size(), options_.threads, kLeastPerThread,
                          [this, &listed](std::size_t k, std::size_t b, std::size_t e) { list_cuts(b, e, listed[k]); });
    cut_index_.reserve(points_.size() / 4);
    for (const Edges& edges : listed)
      for (const auto& [x, y] : edges) {
        const VKey k = cut_key(x, y);
        if (cut_index_.find(k) != EdgeTable::kNone) continue;
        cut_index_.insert(k, static_cast<std::uint32_t>(cuts_.size()));
        cuts_.emplace_back();
        edges_.push_back({x, y});
        ends_.push_back({x, y});
        ends_.push_back({y, x});
      }
    // S28: the cut points, each on its own, so on `threads` threads.
    detail::for_each_range(cuts_.size(), options_.threads, kLeastPerThread, [this](std::size_t b, std::size_t e) {
      for (std::size_t c = b; c < e; ++c) {
        const Vec3 &px = pos_[edges_[c].first], &py = pos_[edges_[c].second];
        const double s = std::clamp(shape_.crossing(px, py), 0.0, 1.0);
        cuts_[c].t = s;
        for (std::size_t d = 0; d < 3; ++d) cuts_[c].pos[d] = px[d] + s * (py[d] - px[d]);
      }
    });
    // S35.7: a cut point placed elsewhere (on a crease), its fraction the
    // parameter of its projection onto the edge, which S6 reads.
    if (options_.place_cut)
      for (std::size_t c = 0; c < cuts_.size(); ++c) {
        const Vec3 &px = pos_[edges_[c].first], &py = pos_[edges_[c].second];
        const Vec3 x = options_.place_cut(px, py, cuts_[c].pos);
        if (x == cuts_[c].pos) continue;
        double num = 0, den = 0;
        for (std::size_t d = 0; d < 3; ++d)
          num += (x[d] - px[d]) * (py[d] - px[d]), den += (py[d] - px[d]) * (py[d] - px[d]);
        cuts_[c].t = std::clamp(num / den, 0.0, 1.0);
        cuts_[c].pos = x;
      }
  }

  /// S5: the cut edges (smaller end first) of lattice tetrahedra [b, e) into
  /// `out`, each at its first use, the tetrahedra in order and the edges of
  /// each in the order of their ends.
  void list_cuts(std::size_t b, std::size_t e, std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) const {
    EdgeTable seen;
    seen.reserve(256);
    for (std::size_t ti = b; ti < e; ++ti) {
      const Ids& t = ids_[ti];
      // S5: an edge is cut only between a negative and a positive end
      // (strict), so a tetrahedron without both has none (most of them).
      bool negative = false, positive = false;
      for (const std::uint32_t p : t) negative = negative || value_[p] < 0, positive = positive || value_[p] > 0;
      if (!(negative && positive)) continue;
      bool has_cut = false;
      for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j) {
          const std::uint32_t x = std::min(t[i], t[j]), y = std::max(t[i], t[j]);
          const int fx = value_[x], fy = value_[y];
          if (!((fx < 0 && fy > 0) || (fx > 0 && fy < 0))) continue;
          has_cut = true;
          const VKey k = cut_key(x, y);
          if (seen.find(k) != EdgeTable::kNone) continue;
          seen.insert(k, 0);
          out.push_back({x, y});
        }
      if (has_cut) detail::check_regular(lattice_tet(ti), fit_.size.L);
    }
  }

  // S6, in increasing position order of v, the other ends w in increasing
  // position order.
  void warp() {
    std::sort(ends_.begin(), ends_.end());
    warped_.assign(points_.size(), 0);
    for (std::size_t b = 0, e = 0; b < ends_.size(); b = e) {
      const std::uint32_t v = ends_[b].first;
      for (e = b; e < ends_.size() && ends_[e].first == v; ++e) {
      }
      const bool v_center = is_center(g_, points_[v]);
      std::uint32_t best = EdgeTable::kNone;
      double best_distance = 0;
      for (std::size_t i = b; i < e; ++i) {
        const std::uint32_t w = ends_[i].second;
        const detail::Cut& c = cuts_[cut_index_.find(cut_key(v, w))];
        if (c.removed) continue;
        const double from_v = v < w ? c.t : 1 - c.t;
        const bool same_kind = v_center == is_center(g_, points_[w]);
        const double alpha = same_kind ? options_.alpha_long : options_.alpha_short;
        if (!(from_v < alpha)) continue;
        const double distance = from_v * std::sqrt(static_cast<double>(length2(v, w)));
        if (best == EdgeTable::kNone || distance < best_distance) best = w, best_distance = distance;
      }
      if (best == EdgeTable::kNone) continue;
      pos_[v] = cuts_[cut_index_.find(cut_key(v, best))].pos;
      warped_[v] = 1;
      value_[v] = 0;
      ++out_.warped;
      for (std::size_t i = b; i < e; ++i) cuts_[cut_index_.find(cut_key(v, ends_[i].second))].removed = true;
    }
    for (const detail::Cut& c : cuts_) out_.cut_points += c.removed ? 0 : 1;
  }

  // S7-S9 over ranges of the lattice tetrahedra, joined in order (S28a).
  void fill() {
    const std::size_t n = ids_.size();
    std::vector<Range> ranges(detail::part_count(n, options_.threads, kLeastPerThread), Range(*this));
    std::vector<std::vector<std::uint32_t>> begins(begin_ ? ranges.size() : 0);
    detail::for_each_part(n, options_.threads, kLeastPerThread,
                          [this, &ranges, &begins](std::size_t k, std::size_t b, std::size_t e) {
                            ranges[k].fill(b, e, begin_ ? &begins[k] : nullptr);
                          });
    // S28d: the lattice's tetrahedra are done with: their memory goes before
    // the join below, which holds the ranges' outputs and their copy at once.
    std::vector<Ids>().swap(ids_);
    std::size_t total = 0;
    for (Range& r : ranges) total += r.tets().size();
    if (begin_) {
      begin_->reserve(n + 1);
      std::size_t offset = 0;
      for (std::size_t k = 0; k < ranges.size(); ++k) {
        for (const std::uint32_t x : begins[k]) begin_->push_back(static_cast<std::uint32_t>(offset + x));
        offset += ranges[k].tets().size();
      }
      begin_->push_back(static_cast<std::uint32_t>(total));
    }
    tets_out_ = std::move(ranges[0].tets());
    levels_out_ = std::move(ranges[0].levels());
    tets_out_.reserve(total);
    levels_out_.reserve(total);
    for (std::size_t k = 1; k < ranges.size(); ++k) {
      tets_out_.insert(tets_out_.end(), ranges[k].tets().begin(), ranges[k].tets().end());
      levels_out_.insert(levels_out_.end(), ranges[k].levels().begin(), ranges[k].levels().end());
      ranges[k].tets() = {};
      ranges[k].levels() = {};
    }
  }

  /// The level of leaf `leaf` (a lattice tetrahedron's vertex 0,
  /// spec/mesh3d.md): from the lattice, or, once it is released (M26.2),
  /// as read before.
  int leaf_level(std::uint32_t leaf) const {
    if (!released_) return level_of(g_, points_[leaf]);
    if (level_[leaf] < 0) throw std::logic_error("flat stuffer: a leaf's level asked of a released lattice");
    return level_[leaf];
  }

  /// Lattice tetrahedron ti as points.
  d3::Tet lattice_tet(std::size_t ti) const {
    const Ids& t = ids_[ti];
    return {points_[t[0]], points_[t[1]], points_[t[2]], points_[t[3]]};
  }

  Stuffed finish() {
    // S8: the output vertices in key order: the lattice vertices used (keys
    // (i, i), in order of i) merged with the cut points used (in key order).
    const std::size_t n = points_.size();
    std::vector<std::uint8_t> used_vertex(n, 0), used_cut(cuts_.size(), 0);
    for (const auto& t : tets_out_)
      for (const std::uint32_t x : t) {
        if (x >= n)
          used_cut[x - n] = 1;
        else
          used_vertex[x] = 1;
      }
    std::vector<VKey> cut_keys;
    for (std::size_t c = 0; c < cuts_.size(); ++c)
      if (used_cut[c]) cut_keys.push_back(cut_key(edges_[c].first, edges_[c].second));
    std::sort(cut_keys.begin(), cut_keys.end());
    std::vector<std::uint32_t> vertex_index(points_.size(), EdgeTable::kNone),
        cut_index(cuts_.size(), EdgeTable::kNone);
    d3::TetMeshF& m = out_.mesh;
    // M26: as many as will be added, so no copy on growth.
    const std::size_t used =
        cut_keys.size() + static_cast<std::size_t>(std::count(used_vertex.begin(), used_vertex.end(), 1));
    m.vertices.reserve(used);
    m.kind.reserve(used);
    if (keys_) keys_->reserve(used);
    const auto add = [&](VKey k) {
      const std::uint32_t index = static_cast<std::uint32_t>(m.vertices.size());
      if (is_cut(k))
        cut_index[cut_index_.find(k)] = index;
      else
        vertex_index[first(k)] = index;
      m.vertices.push_back(pos(k));
      if (keys_) keys_->push_back({points_[first(k)], points_[second(k)]});
      m.kind.push_back(static_cast<std::uint8_t>(is_cut(k)                ? StuffVertex::cut
                                                 : warped_[first(k)] != 0 ? StuffVertex::warped
                                                                          : StuffVertex::lattice));
    };
    std::size_t next_cut = 0;
    for (std::uint32_t i = 0; i < points_.size(); ++i) {
      if (!used_vertex[i]) continue;
      const VKey k = lattice_key(i);
      for (; next_cut < cut_keys.size() && cut_keys[next_cut] < k; ++next_cut) add(cut_keys[next_cut]);
      add(k);
    }
    for (; next_cut < cut_keys.size(); ++next_cut) add(cut_keys[next_cut]);
    for (auto& t : tets_out_)
      for (std::uint32_t& x : t) x = x >= n ? cut_index[x - n] : vertex_index[x];
    m.tets = std::move(tets_out_);
    m.level = std::move(levels_out_);
    return std::move(out_);
  }

  const Shape& shape_;
  const Fit& fit_;
  const G& g_;
  const StuffOptions& options_;
  std::vector<std::uint32_t> table_;  ///< points_ by hash of position, while numbering
  std::vector<d3::Point> points_;     ///< the lattice vertices of the mesh, sorted
  std::vector<Ids> ids_;              ///< the lattice tetrahedra on points_, in order
  std::vector<std::int8_t> value_;    ///< the sign of f (-1, 0, 1), 0 once warped (S28d: a byte)
  std::vector<Vec3> pos_;             ///< in space, warped or not
  std::vector<std::uint8_t> warped_;
  std::vector<detail::Cut> cuts_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges_;  ///< of cuts_, smaller end first
  EdgeTable cut_index_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends_;  ///< (v, w) for each cut edge vw, both ways
  std::vector<std::array<std::uint32_t, 4>> tets_out_;         ///< S7-S9's output, stored as Range::store
  std::vector<int> levels_out_;
  Stuffed out_;
  std::vector<std::array<d3::Point, 2>>* keys_ = nullptr;
  std::vector<std::uint32_t>* begin_ = nullptr;
  std::function<void()> release_;
  bool released_ = false;
  std::vector<int> level_;  ///< M26.2: each leaf's level, read before the lattice is released
};

}  // namespace

Stuffed stuff(const Shape& shape, const Fit& fit, const d3::fast::Lattice& g, const StuffOptions& options,
              PhaseTimes* times) {
  return Stuffer<d3::fast::Lattice>(shape, fit, g, options).run_whole(options.threads, times);
}

Stuffed stuff(const Shape& shape, const Fit& fit, d3::fast::Lattice&& g, const StuffOptions& options,
              PhaseTimes* times) {
  Stuffer<d3::fast::Lattice> stuffer(shape, fit, g, options);
  stuffer.release_after_warp([&g] { const d3::fast::Lattice released = std::move(g); });
  return stuffer.run_whole(options.threads, times);
}

StuffedPart stuff_part(const Shape& shape, const Fit& fit, const d3::fast::Lattice& g, const StuffOptions& options,
                       std::span<const d3::Tet> tets) {
  StuffedPart part;
  Stuffer<d3::fast::Lattice> stuffer(shape, fit, g, options);
  stuffer.record(&part.keys, &part.begin);
  part.stuffed = stuffer.run(tets, nullptr);
  return part;
}

}  // namespace bccmis::stuff
