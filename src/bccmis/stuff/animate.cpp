// A shape moving through a fixed lattice (spec/stuffing.md S14-S16).
#include "bccmis/stuff/animate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "bccmis/balance.h"
#include "bccmis/d3/detail/tetrahedra.h"
#include "bccmis/d3/ops.h"

namespace bccmis::stuff {

Bounds swept_bounds(const Shape& shape, const Vec3& d) {
  Bounds b = shape.bounds();
  for (std::size_t i = 0; i < 3; ++i) {
    b.lo[i] = std::min(b.lo[i], b.lo[i] + d[i]);
    b.hi[i] = std::max(b.hi[i], b.hi[i] + d[i]);
  }
  return b;
}

namespace {
StuffOptions with_level(StuffOptions o, int level) {
  o.max_level = level;
  return o;
}
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
d3::Point shifted(const d3::Point& c, std::int64_t dx, std::int64_t dy, std::int64_t dz) {
  return {c.x + dx, c.y + dy, c.z + dz};
}
/// The 8 children of the cell centred at c with side s.
std::array<d3::Point, 8> children(const d3::Point& c, std::int64_t s) {
  const std::int64_t q = s / 4;
  std::array<d3::Point, 8> out{};
  for (std::size_t i = 0; i < 8; ++i) out[i] = shifted(c, (i & 1) ? q : -q, (i & 2) ? q : -q, (i & 4) ? q : -q);
  return out;
}
}  // namespace

void check_moving_fit(const Fit& fit) {
  const std::int64_t S = d3::level0_side(fit.size);
  if (std::max({fit.size.W, fit.size.H, fit.size.D}) * S >= (std::int64_t{1} << 21))
    throw ShapeError(
        "--animate: the lattice is too fine: " + std::to_string(std::max({fit.size.W, fit.size.H, fit.size.D}) * S) +
        " lattice points along a side, at most 2^21 - 1 (S16's pool packs 21 bits a coordinate)");
}

MovingLattice::MovingLattice(std::shared_ptr<const Shape> shape, const Fit& fit, const StuffOptions& options)
    : shape_(std::move(shape)),
      moved_(shape_),
      fit_((check_moving_fit(fit), fit)),
      options_(with_level(options, fit.size.L)),
      g_(background_fast(*moved_, fit_, options_)),
      reach_(1.05 * std::max(options_.alpha_long * fit_.h, options_.alpha_short * 0.5 * std::sqrt(3.0) * fit_.h)),
      lipschitz_(shape_->distance_is_lipschitz()) {
  // S37 fact 2: e = 1e-9 (R + h), R the largest coordinate of the domain.
  const std::int64_t S = d3::level0_side(fit_.size);
  double R = 0;
  for (const d3::Point& corner : {d3::Point{0, 0, 0}, d3::Point{fit_.size.W * S, fit_.size.H * S, fit_.size.D * S}})
    for (const double x : fit_.to_space(corner)) R = std::max(R, std::abs(x));
  rounding_ = 1e-9 * (R + fit_.h);
  // S39a: the shapes that give a nearest point (S39 fact 1) have |f| the
  // distance to their surface.
  surface_distance_ = lipschitz_ && shape_->nearest(fit_.to_space({0, 0, 0})).point.has_value();
  leaves_.reserve(2 * g_.cell_count());
  std::vector<Candidate> all;
  for (const d3::Point& u : g_.cells()) all.push_back({u, true, {}});
  FrameReport ignored;
  restuff(all, false, ignored);
}

std::vector<d3::Point> MovingLattice::roots() const {
  const std::int64_t s = side(0);
  std::vector<d3::Point> out;
  for (std::int64_t i = 0; i < fit_.size.W; ++i)
    for (std::int64_t j = 0; j < fit_.size.H; ++j)
      for (std::int64_t k = 0; k < fit_.size.D; ++k) out.push_back({s / 2 + i * s, s / 2 + j * s, s / 2 + k * s});
  return out;
}

// S15's refine pass as a descent: S3's test fails on every cell inside a
// cell that fails it, so only cells whose parents pass are visited. On the
// way it collects the refined cells that fail while their parents pass (for
// the coarsen pass; a level-L cell is never refined) and S16's candidates
// near the surface, with the distances it computed: the level-L leaves
// below cells that pass, the coarser leaves that fail, and, to search after
// the coarsen pass, the failing refined cells that may hold some.
void MovingLattice::refine_visit(const d3::Point& c, int level, const detail::DistanceBound& parent,
                                 FrameReport& report, Descent& d) {
  const double s = static_cast<double>(side(level)) * fit_.scale;
  // S37, S38, S39: each comparison asks only if f does not decide it.
  detail::DistanceBound f = known(c, parent);
  const double k = 0.5 * std::sqrt(3.0);
  // near_visit's bound: a leaf inside c may be a candidate.
  const auto may_hold = [&] { return at_most(c, f, k * s + std::max((1 - k) * 0.5 * s + reach_, d.moved)); };
  const bool pass =
      level < fit_.size.L && (level < options_.min_level || at_most(c, f, std::sqrt(3.0) * (0.5 * s) + 4 * fit_.h));
  if (!pass) {
    if (g_.is_center(c)) {
      if (at_most(c, f, std::max(s + reach_, d.moved))) d.near.push_back({c, false, f, true});
    } else {
      d.failing.push_back({c, level});
      if (may_hold()) d.deferred.push_back({c, level});
    }
    return;
  }
  if (g_.is_center(c)) {
    const d3::BalancedRefineResult r = d3::refine_balanced(g_, c);
    report.refines += r.refined.size();
    for (const d3::Point& x : r.refined) changed_.push_back({x, *d3::refined_center_level(fit_.size, x)});
  }
  if (level + 1 < fit_.size.L) {
    const detail::DistanceBound below = to_children(f, level);
    for (const d3::Point& child : children(c, side(level))) refine_visit(child, level + 1, below, report, d);
    return;
  }
  // The children are level-L leaves.
  if (!may_hold()) return;
  const detail::DistanceBound below = to_children(f, level);
  for (const d3::Point& child : children(c, side(level))) {
    detail::DistanceBound fc = known(child, below);
    if (at_most(child, fc, std::max(0.5 * s + reach_, d.moved))) d.near.push_back({child, false, fc, true});
  }
}

// Coarsens the refined cell c (which fails the test, as every cell inside
// it) from the bottom up, as far as balance allows; true if anything changed.
bool MovingLattice::coarsen_subtree(const d3::Point& c, int level, FrameReport& report) {
  bool changed = false, leaves = true;
  for (const d3::Point& child : children(c, side(level)))
    if (!g_.is_center(child)) {
      changed = coarsen_subtree(child, level + 1, report) || changed;
      leaves = leaves && g_.is_center(child);
    }
  if (leaves && !g_.can_coarsen(c)) {
    g_.coarsen(c);
    changed_.push_back({c, level});
    ++report.coarsens;
    changed = true;
  }
  return changed;
}

// S16's candidates: the leaves that can be active now, |f(u)| <= s_u + 1.05 r_w,
// or whose sign can have changed since the last frame, |f(u)| <= the
// distance moved (the surface passed u on the way).
void MovingLattice::near_visit(const d3::Point& c, int level, const detail::DistanceBound& parent, double moved,
                               std::vector<Candidate>& out) {
  const double s = static_cast<double>(side(level)) * fit_.scale;
  detail::DistanceBound f = known(c, parent);  // S37, S38, S39
  if (g_.is_center(c)) {
    if (at_most(c, f, std::max(s + reach_, moved))) out.push_back({c, false, f, true});
    return;
  }
  // A leaf u of side s_u inside c is within sqrt(3)/2 (s - s_u) of c's
  // center, and s_u <= s / 2: it passes only if f(c) <= sqrt(3)/2 s +
  // max((1 - sqrt(3)/2) s / 2 + reach, moved).
  const double k = 0.5 * std::sqrt(3.0);
  if (!at_most(c, f, k * s + std::max((1 - k) * 0.5 * s + reach_, moved))) return;
  const detail::DistanceBound below = to_children(f, level);
  for (const d3::Point& child : children(c, side(level))) near_visit(child, level + 1, below, moved, out);
}

detail::DistanceBound MovingLattice::to_children(const detail::DistanceBound& f, int level) const {
  // S38: a child's center lies sqrt(3)/4 s from its parent's; f is
  // 1-Lipschitz in the point only where S37 fact 1 says so.
  if (!lipschitz_) return {};
  return detail::widened(f, 0.25 * std::sqrt(3.0) * static_cast<double>(side(level)) * fit_.scale, rounding_);
}

// The leaf holding the points just beside p in the direction of `octant`
// (each component -1 or 1); false outside the domain.
bool MovingLattice::leaf_at(const d3::Point& p, const std::array<int, 3>& octant, int from, d3::Point& out) const {
  const std::int64_t S = d3::level0_side(fit_.size);
  const std::int64_t extent[3] = {fit_.size.W * S, fit_.size.H * S, fit_.size.D * S};
  const std::int64_t at[3] = {octant[0] > 0 ? p.x : p.x - 1, octant[1] > 0 ? p.y : p.y - 1,
                              octant[2] > 0 ? p.z : p.z - 1};
  for (int i = 0; i < 3; ++i)
    if (at[i] < 0 || at[i] >= extent[i]) return false;
  // The leaf is at level `from` or finer when balance holds around the
  // changed cell; from level 0 otherwise.
  for (int i = 0; i <= fit_.size.L; ++i) {
    const int level = i + from <= fit_.size.L ? i + from : i + from - fit_.size.L - 1;
    const std::int64_t s = side(level);
    const d3::Point c{at[0] / s * s + s / 2, at[1] / s * s + s / 2, at[2] / s * s + s / 2};
    if (g_.is_center(c)) {
      out = c;
      return true;
    }
  }
  throw std::logic_error("MovingLattice: no leaf holds the points beside " + d3::to_string(p));
}

// S16: the leaves whose lattice tetrahedra may have changed with this step's
// refines and coarsens: the changed cells and their children that are
// leaves, and the leaves beside the changed cells' face centers and edge
// midpoints found by the probes below.
std::vector<d3::Point> MovingLattice::lattice_dirty() {
  // Probes: from a face center of a changed cell, each octant pointing out
  // of it (any leaf there shares part of that face); from an edge midpoint,
  // the two octants pointing out across the edge (a leaf there shares only
  // the edge, and changes only when it has the cell's level: the midpoint
  // is then its own edge midpoint; finer, it is its corner). `only` is that
  // level, or -1.
  struct Probe {
    d3::Point p;
    int octant, from, only;
    bool operator<(const Probe& o) const { return std::tie(p, octant, only) < std::tie(o.p, o.octant, o.only); }
  };
  std::vector<Probe> probes;
  std::vector<d3::Point> out;
  for (const auto& [c, level] : changed_) {
    const std::int64_t h = side(level) / 2;
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j)
        for (int k = -1; k <= 1; ++k) {
          const int d[3] = {i, j, k};
          const int nonzero = (i != 0) + (j != 0) + (k != 0);
          if (nonzero == 0 || nonzero == 3) continue;  // the center (inside) or a corner (a node throughout)
          for (int o = 0; o < 8; ++o) {
            bool outward = true, inward = true;
            for (int a = 0; a < 3; ++a) {
              if (d[a] == 0) continue;
              const bool up = ((o >> a) & 1) != 0;
              outward = outward && up == (d[a] > 0);
              inward = inward && up != (d[a] > 0);
            }
            if (nonzero == 1 && !inward) probes.push_back({shifted(c, i * h, j * h, k * h), o, level - 1, -1});
            if (nonzero == 2 && outward) probes.push_back({shifted(c, i * h, j * h, k * h), o, level, level});
          }
        }
    // The changed cell and its children: the leaves among them are new or
    // lose or gain a node.
    if (g_.is_center(c)) out.push_back(c);
    for (const d3::Point& child : children(c, side(level)))
      if (g_.is_center(child)) out.push_back(child);
  }
  std::sort(probes.begin(), probes.end());
  probes.erase(std::unique(probes.begin(), probes.end(),
                           [](const Probe& a, const Probe& b) { return a.p == b.p && a.octant == b.octant; }),
               probes.end());
  d3::Point u;
  for (const Probe& q : probes)
    if (leaf_at(q.p, {(q.octant & 1) ? 1 : -1, (q.octant & 2) ? 1 : -1, (q.octant & 4) ? 1 : -1}, std::max(0, q.from),
                u) &&
        (q.only < 0 || g_.level_of(u) == q.only))
      out.push_back(u);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

namespace {
/// A lattice point as one integer (S16's pool; checked to fit by the
/// constructor).
std::uint64_t pack(const d3::Point& p) {
  return static_cast<std::uint64_t>(p.x) << 42 | static_cast<std::uint64_t>(p.y) << 21 |
         static_cast<std::uint64_t>(p.z);
}
}  // namespace

std::size_t MovingLattice::PackedIndex::home(std::uint64_t k) const {
  // splitmix64's finalizer: every bit of the packed point reaches the low
  // bits (a bare multiplicative hash read at bits 20 and up leaves the x
  // field, at bit 42, out of them: every x of a (y, z) shared one home).
  k = (k ^ (k >> 30)) * 0xBF58476D1CE4E5B9ull;
  k = (k ^ (k >> 27)) * 0x94D049BB133111EBull;
  return static_cast<std::size_t>(k ^ (k >> 31)) & (keys_.size() - 1);
}

std::uint32_t MovingLattice::PackedIndex::find(std::uint64_t k) const {
  if (keys_.empty()) return kNone;
  for (std::size_t i = home(k);; i = (i + 1) & (keys_.size() - 1)) {
    if (keys_[i] == k) return values_[i];
    if (keys_[i] == kEmpty) return kNone;
  }
}

std::pair<std::uint32_t, bool> MovingLattice::PackedIndex::insert(std::uint64_t k, std::uint32_t v) {
  if (2 * (used_ + 1) > keys_.size()) grow();
  std::size_t i = home(k);
  for (; keys_[i] != kEmpty; i = (i + 1) & (keys_.size() - 1))
    if (keys_[i] == k) return {values_[i], false};
  keys_[i] = k;
  values_[i] = v;
  ++used_;
  return {v, true};
}

void MovingLattice::PackedIndex::erase(std::uint64_t k) {
  const std::size_t mask = keys_.size() - 1;
  std::size_t i = home(k);
  while (keys_[i] != k) {
    if (keys_[i] == kEmpty) return;
    i = (i + 1) & mask;
  }
  // Backward shift: move up every later key of the run whose home does not
  // lie cyclically in (i, j].
  for (std::size_t j = (i + 1) & mask; keys_[j] != kEmpty; j = (j + 1) & mask) {
    const std::size_t h = home(keys_[j]);
    const bool stays = i <= j ? (i < h && h <= j) : (i < h || h <= j);
    if (stays) continue;
    keys_[i] = keys_[j];
    values_[i] = values_[j];
    i = j;
  }
  keys_[i] = kEmpty;
  --used_;
}

void MovingLattice::PackedIndex::grow() {
  std::vector<std::uint64_t> keys = std::move(keys_);
  std::vector<std::uint32_t> values = std::move(values_);
  keys_.assign(std::max<std::size_t>(1024, 2 * keys.size()), kEmpty);
  values_.assign(keys_.size(), 0);
  used_ = 0;
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (keys[i] != kEmpty) insert(keys[i], values[i]);
}

detail::DistanceBound MovingLattice::remembered(const d3::Point& p) const {
  const std::uint32_t i = asked_index_.find(pack(p));
  if (i == PackedIndex::kNone) return {};
  const Asked& a = asked_[i];
  const double drift = std::hypot(offset_[0] - a.at[0], offset_[1] - a.at[1], offset_[2] - a.at[2]);
  // S37: the value itself at the offset it was asked at, a bound elsewhere
  // only for a 1-Lipschitz distance.
  if (drift != 0 && !lipschitz_) return {};
  detail::DistanceBound f = detail::drifted(a.f, drift, rounding_);
  if (!lipschitz_ || !a.nearest) return f;
  f.nearest = i;  // S39
  return f;
}

detail::DistanceBound MovingLattice::known(const d3::Point& p, const detail::DistanceBound& parent) const {
  // S37, S38; S39's point comes with either.
  return detail::both(remembered(p), parent);
}

std::optional<bool> MovingLattice::decide(const d3::Point& p, detail::DistanceBound& f, double t) const {
  if (const std::optional<bool> decided = f.at_most(t)) return decided;
  // S39: the point's distance, computed only where S37 and S38 leave the
  // comparison open.
  if (f.nearest == detail::DistanceBound::kNoPoint || f.exact()) return std::nullopt;
  // The point found then, moved with the shape, is a point of the surface
  // now: |f(p)| is at most its distance from p.
  const Asked& a = asked_[f.nearest];
  if (!a.nearest) return std::nullopt;
  const Vec3& q = *a.nearest;
  f = detail::closer(f, fit_.to_space(p),
                     {q[0] + (offset_[0] - a.at[0]), q[1] + (offset_[1] - a.at[1]), q[2] + (offset_[2] - a.at[2])},
                     rounding_);
  return f.at_most(t);
}

bool MovingLattice::at_most(const d3::Point& p, detail::DistanceBound& f, double t) {
  if (const std::optional<bool> decided = decide(p, f, t)) return *decided;
  Shape::Nearest n = moved_->nearest(fit_.to_space(p));
  const double value = n.distance;
  const auto [i, inserted] = asked_index_.insert(pack(p), static_cast<std::uint32_t>(asked_.size()));
  if (inserted)
    asked_.push_back({value, offset_, n.point});
  else
    asked_[i] = {value, offset_, n.point};
  f = {value, value, lipschitz_ && n.point ? i : detail::DistanceBound::kNoPoint};
  return value <= t;
}

void MovingLattice::release(Leaf& leaf) {
  for (const auto& t : leaf.inside)
    for (const std::uint32_t v : t)
      if (--refs_[v] == 0) {
        index_.erase(pack(point_[v]));
        free_.push_back(v);
      }
  leaf.inside.clear();
}

std::uint32_t MovingLattice::acquire(const d3::Point& p) {
  const std::uint32_t next = free_.empty() ? static_cast<std::uint32_t>(point_.size()) : free_.back();
  const auto [v, inserted] = index_.insert(pack(p), next);
  if (inserted) {
    if (free_.empty()) {
      point_.push_back(p);
      refs_.push_back(0);
    } else {
      free_.pop_back();
      point_[v] = p;
    }
  }
  ++refs_[v];
  return v;
}

// S16: settle each candidate leaf as active (stuffed this frame), inside
// (its tetrahedra are output as they are) or outside (no output), its
// lattice tetrahedra computed again where the lattice changed; then stuff
// the active leaves and put the frame's mesh together.
void MovingLattice::restuff(const std::vector<Candidate>& candidates, bool descended, FrameReport& report) {
  std::vector<d3::Tet>& tets = tets_;
  std::vector<d3::Tet> fresh;
  tets.clear();
  std::vector<d3::Point> active;
  for (const auto& [u, relattice, known, near, born] : candidates) {
    Leaf& leaf = leaves_[u];
    if (leaf.level < 0) leaf.level = g_.level_of(u);
    leaf.stale = leaf.stale || relattice;
    const double s = static_cast<double>(side(leaf.level)) * fit_.scale;
    // The sign only where it decides, inside or outside; what the descent
    // and earlier frames know of the distance spares a query (S37 fact 4).
    const Vec3 at = fit_.to_space(u);
    bool is_active = false;
    int sign = 0;  // of f, when asked here
    if (descended && !near && (!born || surface_distance_)) {
      // S38a: a leaf throughout the step that the descent did not find has
      // |f| > max(s + 1.05 r_w, m): inactive; its side is asked alone. S39a:
      // so has a leaf the step made, when |f| is the distance to the surface.
      is_active = false;
    } else if (detail::DistanceBound bound = this->known(u, known);
               const std::optional<bool> decided = decide(u, bound, s + reach_)) {
      is_active = *decided;
    } else {
      const double f = moved_->signed_distance(at);
      is_active = std::abs(f) <= s + reach_;
      sign = (f > 0) - (f < 0);
    }
    // Inactive: |f| > s + 1.05 r_w > 0, so the side is the sign of f.
    if (!is_active && (sign != 0 ? sign : moved_->side(at)) > 0) {
      release(leaf);  // outside: every vertex is outside; its tetrahedra wait until needed
      continue;
    }
    if (leaf.stale) {
      fresh.clear();
      d3::detail::leaf_tetrahedra(g_, u, fresh);
      if (fresh != leaf.lattice) {
        release(leaf);
        std::swap(leaf.lattice, fresh);
      }
      leaf.stale = false;
    }
    if (is_active) {
      // A vertex of its tetrahedra may be warped, or an edge cut.
      release(leaf);
      active.push_back(u);
      tets.insert(tets.end(), leaf.lattice.begin(), leaf.lattice.end());
    } else if (leaf.inside.empty()) {
      for (const d3::Tet& t : leaf.lattice)
        leaf.inside.push_back({acquire(t[0]), acquire(t[1]), acquire(t[2]), acquire(t[3])});
    }
  }
  report.restuffed_leaves = active.size();
  report.restuffed_tetrahedra = tets.size();
  active_ = std::move(active);
  assemble(stuff_part(*moved_, fit_, g_, options_, tets));
}

void MovingLattice::assemble(const StuffedPart& part) {
  // The buffers of the last frame are reused.
  Stuffed& out = stuffed_;
  d3::TetMeshF& m = out.mesh;
  m.vertices.clear();
  m.kind.clear();
  m.tets.clear();
  m.level.clear();
  out.lattice_tetrahedra = 0;
  std::vector<std::uint32_t> index(point_.size(), 0xFFFFFFFFu);
  for (std::uint32_t v = 0; v < point_.size(); ++v) {
    if (refs_[v] == 0) continue;
    index[v] = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.push_back(fit_.to_space(point_[v]));
    m.kind.push_back(static_cast<std::uint8_t>(StuffVertex::lattice));
  }
  for (const auto& [u, leaf] : leaves_) {
    if (!leaf.stale) out.lattice_tetrahedra += leaf.lattice.size();
    if (leaf.inside.empty()) continue;
    for (const auto& t : leaf.inside) {
      m.tets.push_back({index[t[0]], index[t[1]], index[t[2]], index[t[3]]});
      m.level.push_back(leaf.level);
    }
  }
  // The active leaves' stuffing: its lattice vertices that inside leaves
  // use too are the same vertices.
  const d3::TetMeshF& a = part.stuffed.mesh;
  std::vector<std::uint32_t> to(a.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    if (a.kind[i] == static_cast<std::uint8_t>(StuffVertex::lattice))
      if (const std::uint32_t v = index_.find(pack(part.keys[i][0])); v != PackedIndex::kNone) {
        to[i] = index[v];
        continue;
      }
    to[i] = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.push_back(a.vertices[i]);
    m.kind.push_back(a.kind[i]);
  }
  for (std::size_t t = 0; t < a.tets.size(); ++t) {
    m.tets.push_back({to[a.tets[t][0]], to[a.tets[t][1]], to[a.tets[t][2]], to[a.tets[t][3]]});
    m.level.push_back(a.level[t]);
  }
  out.cut_points = part.stuffed.cut_points;
  out.warped = part.stuffed.warped;
}

FrameReport MovingLattice::step(const Vec3& offset) {
  FrameReport report;
  const double moved = std::hypot(offset[0] - offset_[0], offset[1] - offset_[1], offset[2] - offset_[2]);
  offset_ = offset;
  moved_ = translated(shape_, offset);
  changed_.clear();
  const auto t0 = std::chrono::steady_clock::now();
  // S15: refine every cell that passes S3's test (by descent, S16).
  const std::vector<d3::Point> top = roots();
  // Then coarsen the refined cells that fail it, bottom up, until balance
  // lets no more go.
  Descent descent;
  descent.moved = moved * 1.01;
  for (const d3::Point& c : top) refine_visit(c, 0, {}, report, descent);
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [c, level] : descent.failing)
      if (!g_.is_center(c)) changed = coarsen_subtree(c, level, report) || changed;
  }
  report.lattice_seconds = since(t0);
  report.leaves = g_.cell_count();
  const auto t1 = std::chrono::steady_clock::now();
  // S16: the leaves that left go; the candidates are the leaves whose
  // lattice tetrahedra changed, the last frame's active leaves and the
  // leaves near the surface or passed by it.
  std::vector<d3::Point> gone;
  for (const auto& [c, level] : changed_) {
    gone.push_back(c);
    for (const d3::Point& child : children(c, side(level))) gone.push_back(child);
  }
  std::sort(gone.begin(), gone.end());
  gone.erase(std::unique(gone.begin(), gone.end()), gone.end());
  for (const d3::Point& c : gone)
    if (!g_.is_center(c))
      if (auto it = leaves_.find(c); it != leaves_.end()) {
        release(it->second);
        leaves_.erase(it);
      }
  // Each candidate leaf once: its lattice changed if any entry says so, its
  // distance if any entry knows it.
  std::vector<Candidate> all = std::move(descent.near);
  for (const d3::Point& u : lattice_dirty()) all.push_back({u, true, {}});
  // S38a: the leaves this step made (a changed cell or a child of one).
  for (const d3::Point& u : gone)
    if (g_.is_center(u)) all.push_back({u, true, {}, false, true});
  for (const d3::Point& u : active_) all.push_back({u, false, {}});
  for (const auto& [c, level] : descent.deferred) near_visit(c, level, {}, descent.moved, all);
  std::sort(all.begin(), all.end(), [](const Candidate& a, const Candidate& b) { return a.u < b.u; });
  std::vector<Candidate> candidates;
  for (const Candidate& c : all) {
    if (!candidates.empty() && candidates.back().u == c.u) {
      candidates.back().relattice = candidates.back().relattice || c.relattice;
      candidates.back().f = detail::both(candidates.back().f, c.f);
      candidates.back().near = candidates.back().near || c.near;
      candidates.back().born = candidates.back().born || c.born;
    } else {
      candidates.push_back(c);
    }
  }
  // The last frame's active leaves may have gone since.
  std::erase_if(candidates, [&](const Candidate& c) { return !c.relattice && !g_.is_center(c.u); });
  restuff(candidates, true, report);
  report.stuff_seconds = since(t1);
  return report;
}

}  // namespace bccmis::stuff
