// S35.7: cut points placed on the creases before warping (crease_cuts.h).
#include "bccmis/stuff/crease_cuts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "bccmis/d3/mesh.h"
#include "bccmis/io/regions.h"
#include "bccmis/stuff/stopwatch.h"

namespace bccmis::stuff {

namespace {

using Cell = std::array<std::int64_t, 3>;

/// The curves' segments filed in cubes of side `side` by the boxes they
/// reach within `reach`.
class SegmentGrid {
 public:
  SegmentGrid(const Features& f, double side, double reach) : side_(side) {
    for (const FeatureCurve& c : f.curves)
      for (std::size_t i = 1; i < c.points.size(); ++i) {
        const auto id = static_cast<std::uint32_t>(segments_.size());
        segments_.push_back({c.points[i - 1], c.points[i]});
        Vec3 lo, hi;
        for (std::size_t d = 0; d < 3; ++d) {
          lo[d] = std::min(c.points[i - 1][d], c.points[i][d]) - reach;
          hi[d] = std::max(c.points[i - 1][d], c.points[i][d]) + reach;
        }
        const Cell a = cell(lo), b = cell(hi);
        for (std::int64_t x = a[0]; x <= b[0]; ++x)
          for (std::int64_t y = a[1]; y <= b[1]; ++y)
            for (std::int64_t z = a[2]; z <= b[2]; ++z) cells_[{x, y, z}].push_back(id);
      }
  }
  /// The nearest point of the segments filed at x's cube (a tie: the
  /// first segment, in curve order); distance HUGE_VAL when none.
  CurvePoint nearest(const Vec3& x) const {
    CurvePoint best{HUGE_VAL, 0, x};
    const auto it = cells_.find(cell(x));
    if (it == cells_.end()) return best;
    for (const std::uint32_t id : it->second) {
      const CurvePoint p = nearest_on_segment(segments_[id].first, segments_[id].second, x);
      if (p.distance < best.distance) best = p;
    }
    return best;
  }

 private:
  Cell cell(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p[0] / side_)), static_cast<std::int64_t>(std::floor(p[1] / side_)),
            static_cast<std::int64_t>(std::floor(p[2] / side_))};
  }
  double side_;
  std::vector<std::pair<Vec3, Vec3>> segments_;
  std::map<Cell, std::vector<std::uint32_t>> cells_;
};

using Edge = std::pair<Vec3, Vec3>;

/// A placed cut point: its edge and its reference place on it.
struct Placed {
  Edge edge;
  Vec3 reference{};
};

bool in_interval(const std::array<Vec3, 4>& p) {
  for (const double a : d3::dihedral_angles(p))
    if (!(a >= kDihedralBounds[0] && a <= kDihedralBounds[1])) return false;
  return true;
}

/// One of S35.8's candidates: its mesh conformed (S30-S35).
struct Candidate {
  Stuffed stuffed;
  std::vector<std::array<std::uint32_t, 3>> boundary;
  FeatureConformity conformity;
};

Candidate conformed(Stuffed stuffed, const Features& features, double h, bool split_edges, bool split_chords,
                    double* seconds) {
  const auto t0 = Clock::now();
  Candidate c{std::move(stuffed), {}, {}};
  (void)io::regions_of(c.stuffed.mesh.tets, &c.boundary);
  c.conformity = conform_features(c.stuffed.mesh, c.boundary, features, h, split_edges, true, split_chords);
  // S35's splits and S35.9's flips changed the tetrahedra: their boundary again.
  if (c.conformity.splits > 0 || c.conformity.flips > 0) (void)io::regions_of(c.stuffed.mesh.tets, &c.boundary);
  if (seconds) *seconds += seconds_since(t0);
  return c;
}

}  // namespace

Stuffed stuff_on_creases(const Shape& shape, const Fit& fit, const StuffOptions& options, const Features& features,
                         double delta, CreaseCuts* report, PhaseTimes* times,
                         const std::function<void(std::size_t, double)>& on_lattice) {
  CreaseCuts local;
  CreaseCuts& out = report ? *report : local;
  out = {};
  if (features.curves.empty() || !(delta > 0)) {
    out.rounds = 1;
    return stuff_fitted(shape, fit, options, Impl::fast, times, on_lattice);
  }
  const double reach = delta * fit.h;
  const SegmentGrid grid(features, fit.h, reach);
  std::set<Edge> excluded;
  // Every round's phases, added up.
  PhaseTimes round_times;
  const auto add = [times](const PhaseTimes& t) {
    if (!times) return;
    times->lattice += t.lattice, times->mesh += t.mesh, times->cut += t.cut, times->warp += t.warp;
    times->stencils += t.stencils;
  };
  if (times) *times = {};
  constexpr std::size_t kRounds = 8;
  for (std::size_t round = 0;; ++round) {
    out.rounds = round + 1;
    if (round == kRounds) break;
    // S35.7's placement, in the order of the cut edges.
    std::map<Vec3, Placed> placed;
    StuffOptions o = options;
    o.place_cut = [&](const Vec3& p, const Vec3& q, const Vec3& x) {
      if (excluded.count({p, q})) return x;
      const CurvePoint c = grid.nearest(x);
      if (!(c.distance <= reach) || c.point == x || placed.count(c.point)) return x;
      Vec3 pq{q[0] - p[0], q[1] - p[1], q[2] - p[2]};
      double num = 0, den = 0;
      for (std::size_t d = 0; d < 3; ++d) num += (c.point[d] - p[d]) * pq[d], den += pq[d] * pq[d];
      const double t = std::clamp(num / den, 0.0, 1.0);
      placed[c.point] = {{p, q}, {p[0] + t * pq[0], p[1] + t * pq[1], p[2] + t * pq[2]}};
      return c.point;
    };
    Stuffed s = stuff_fitted(shape, fit, o, Impl::fast, &round_times, round == 0 ? on_lattice : nullptr);
    add(round_times);
    // S35.7's guard: every tetrahedron in S10's interval, and positively
    // oriented at the reference places of its placed vertices.
    const d3::TetMeshF& m = s.mesh;
    std::vector<const Placed*> at(m.vertices.size(), nullptr);
    std::size_t count = 0;
    for (std::size_t v = 0; v < m.vertices.size(); ++v)
      if (const auto it = placed.find(m.vertices[v]); it != placed.end()) at[v] = &it->second, ++count;
    bool unplaced_failure = false;
    std::size_t newly = 0;
    for (const auto& t : m.tets) {
      const std::array<Vec3, 4> p{m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], m.vertices[t[3]]};
      bool any = false;
      std::array<Vec3, 4> r = p;
      for (std::size_t i = 0; i < 4; ++i)
        if (at[t[i]]) any = true, r[i] = at[t[i]]->reference;
      if (in_interval(p) && (!any || orientation(r[0], r[1], r[2], r[3]) > 0)) continue;
      if (!any) {
        unplaced_failure = true;
        break;
      }
      for (const std::uint32_t v : t)
        if (at[v] && excluded.insert(at[v]->edge).second) ++newly;
    }
    if (unplaced_failure) break;
    if (newly == 0) {
      out.placed = count;
      out.excluded = excluded.size();
      return s;
    }
  }
  // The guard gave up: S5-S9's mesh.
  out.none = true;
  out.excluded = excluded.size();
  Stuffed s = stuff_fitted(shape, fit, options, Impl::fast, &round_times);
  add(round_times);
  return s;
}

CreaseConformed stuff_and_conform_on_creases(const Shape& shape, const Fit& fit, const StuffOptions& options,
                                             const Features& features, double delta, double h, bool split_edges,
                                             bool split_chords, PhaseTimes* times, double* feature_seconds,
                                             const std::function<void(std::size_t, double)>& on_lattice) {
  if (times) *times = {};
  if (feature_seconds) *feature_seconds = 0;
  // A: the run without S35.7, the same calls as mesh_shape's.
  Stuffed without = stuff_fitted(shape, fit, options, Impl::fast, times, on_lattice);
  return conform_on_creases(std::move(without), shape, fit, options, features, delta, h, split_edges, split_chords,
                            times, feature_seconds);
}

CreaseConformed conform_on_creases(Stuffed without, const Shape& shape, const Fit& fit, const StuffOptions& options,
                                   const Features& features, double delta, double h, bool split_edges,
                                   bool split_chords, PhaseTimes* times, double* feature_seconds) {
  const auto add = [times](const PhaseTimes& t) {
    if (!times) return;
    times->lattice += t.lattice, times->mesh += t.mesh, times->cut += t.cut, times->warp += t.warp;
    times->stencils += t.stencils;
  };
  CreaseConformed r;
  PhaseTimes t;
  Candidate a = conformed(std::move(without), features, h, split_edges, split_chords, feature_seconds);
  const auto keep = [&r](Candidate&& c, CreaseCandidate which, std::size_t placed) {
    r.stuffed = std::move(c.stuffed);
    r.boundary = std::move(c.boundary);
    r.conformity = std::move(c.conformity);
    r.kept = which;
    r.placed_kept = placed;
  };
  // B: S35.7 with every curve.
  {
    Candidate b = conformed(stuff_on_creases(shape, fit, options, features, delta, &r.all_curves, &t), features, h,
                            split_edges, split_chords, feature_seconds);
    add(t);
    r.candidates = 2;
    if (gains_on(b.conformity, a.conformity)) {
      keep(std::move(b), CreaseCandidate::all_curves, r.all_curves.placed);
      return r;
    }
    // G: the curves B conforms and A does not.
    Features gained = features;
    gained.curves.clear();
    for (const std::size_t i : b.conformity.conformed_curves)
      if (!std::binary_search(a.conformity.conformed_curves.begin(), a.conformity.conformed_curves.end(), i))
        gained.curves.push_back(features.curves[i]);
    if (!gained.curves.empty()) {
      // C: S35.7 with G's curves only (b freed first: two meshes at once).
      b = {};
      CreaseCuts cuts;
      Candidate c = conformed(stuff_on_creases(shape, fit, options, gained, delta, &cuts, &t), features, h, split_edges,
                              split_chords, feature_seconds);
      add(t);
      r.candidates = 3;
      if (gains_on(c.conformity, a.conformity)) {
        keep(std::move(c), CreaseCandidate::gained_curves, cuts.placed);
        return r;
      }
    }
  }
  keep(std::move(a), CreaseCandidate::without, 0);
  return r;
}

}  // namespace bccmis::stuff
