// The reference stuffer: S5-S9 of spec/stuffing.md written on ordered maps
// keyed by lattice points, the oracle of the flat stuffer (flat_stuffer.cpp,
// tests/stuff/stuffing_fast_test.cpp). stuff() on a d3::Graph.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "bccmis/d3/point.h"
#include "bccmis/stuff/detail/stencils.h"
#include "bccmis/stuff/detail/stuffer.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

namespace {

/// A vertex of the output (S8's key): a lattice vertex p is (p, p), the cut
/// point on lattice edge xy is (min(x, y), max(x, y)).
struct VKey {
  d3::Point a, b;
  bool is_cut() const { return !(a == b); }
  friend auto operator<=>(const VKey&, const VKey&) = default;
};

class ReferenceStuffer : detail::Stencils<ReferenceStuffer, d3::Point, VKey> {
 public:
  ReferenceStuffer(const Shape& shape, const Fit& fit, const d3::Graph& g, const StuffOptions& options)
      : shape_(shape), fit_(fit), g_(g), options_(options) {}

  Stuffed run(std::vector<d3::Tet> tets, PhaseTimes* times) {
    detail::PhaseClock clock(times);
    tets_ = std::move(tets);
    out_.lattice_tetrahedra = tets_.size();
    evaluate();
    cut();
    clock.lap(&PhaseTimes::cut);
    warp();
    clock.lap(&PhaseTimes::warp);
    for (const d3::Tet& t : tets_) fill(t);
    Stuffed s = finish();
    clock.lap(&PhaseTimes::stencils);
    return s;
  }

 private:
  friend class detail::Stencils<ReferenceStuffer, d3::Point, VKey>;

  // What the stencils (detail/stencils.h) ask of a stuffer.
  static VKey lattice_key(const d3::Point& p) { return {p, p}; }
  static VKey cut_key(const d3::Point& x, const d3::Point& y) { return x < y ? VKey{x, y} : VKey{y, x}; }
  static std::int64_t length2(const d3::Point& p, const d3::Point& q) { return detail::length2(p, q); }
  static d3::Point point_of(const VKey& k) { return k.a; }
  double value(const d3::Point& p) const { return value_.at(p); }
  Vec3 pos(const VKey& k) const {
    if (k.is_cut()) return cuts_.at({k.a, k.b}).pos;
    const auto it = warped_.find(k.a);
    return it != warped_.end() ? it->second : fit_.to_space(k.a);
  }

  void evaluate() {
    for (const d3::Tet& t : tets_)
      for (const d3::Point& p : t)
        if (!value_.count(p)) value_.emplace(p, shape_.signed_distance(fit_.to_space(p)));
  }

  // S5
  void cut() {
    for (const d3::Tet& t : tets_) {
      bool has_cut = false;
      for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j) {
          d3::Point x = t[i], y = t[j];
          if (y < x) std::swap(x, y);
          const double fx = value(x), fy = value(y);
          if (!((fx < 0 && fy > 0) || (fx > 0 && fy < 0))) continue;
          has_cut = true;
          if (cuts_.count({x, y})) continue;
          const Vec3 px = fit_.to_space(x), py = fit_.to_space(y);
          const double s = std::clamp(shape_.crossing(px, py), 0.0, 1.0);
          detail::Cut c;
          c.t = s;
          for (std::size_t k = 0; k < 3; ++k) c.pos[k] = px[k] + s * (py[k] - px[k]);
          cuts_.emplace(std::make_pair(x, y), c);
          at_[x].push_back(y);
          at_[y].push_back(x);
        }
      if (has_cut) detail::check_regular(t, fit_.size.L);
    }
  }

  bool same_kind(const d3::Point& p, const d3::Point& q) const { return g_.is_center(p) == g_.is_center(q); }

  // S6, in increasing position order.
  void warp() {
    for (auto& [v, others] : at_) {
      std::sort(others.begin(), others.end());
      const d3::Point* best = nullptr;
      double best_distance = 0;
      for (const d3::Point& w : others) {
        const auto key = v < w ? std::make_pair(v, w) : std::make_pair(w, v);
        const detail::Cut& c = cuts_.at(key);
        if (c.removed) continue;
        const double from_v = v < w ? c.t : 1 - c.t;
        const double alpha = same_kind(v, w) ? options_.alpha_long : options_.alpha_short;
        if (!(from_v < alpha)) continue;
        const double distance = from_v * std::sqrt(static_cast<double>(length2(v, w)));
        if (!best || distance < best_distance) best = &w, best_distance = distance;
      }
      if (!best) continue;
      const d3::Point w = *best;
      warped_[v] = cuts_.at(v < w ? std::make_pair(v, w) : std::make_pair(w, v)).pos;
      value_[v] = 0;
      for (const d3::Point& x : others) cuts_.at(v < x ? std::make_pair(v, x) : std::make_pair(x, v)).removed = true;
    }
    out_.warped = warped_.size();
    for (const auto& [k, c] : cuts_) out_.cut_points += c.removed ? 0 : 1;
  }

  // S7
  void fill(const d3::Tet& t) {
    bool warped = false;
    for (const d3::Point& p : t) warped = warped || warped_.count(p);
    if (warped) detail::check_regular(t, fit_.size.L);
    const int level = g_.level_of(t[0]);
    Stencils::fill(t, [level] { return level; });
  }

  Stuffed finish() {
    std::map<VKey, std::uint32_t> index;
    for (const auto& t : tets_out_)
      for (const VKey& k : t) index.emplace(k, 0);
    d3::TetMeshF& m = out_.mesh;
    std::uint32_t next = 0;
    for (auto& [k, i] : index) {
      i = next++;
      m.vertices.push_back(pos(k));
      m.kind.push_back(static_cast<std::uint8_t>(k.is_cut()           ? StuffVertex::cut
                                                 : warped_.count(k.a) ? StuffVertex::warped
                                                                      : StuffVertex::lattice));
    }
    for (std::size_t i = 0; i < tets_out_.size(); ++i) {
      const auto& t = tets_out_[i];
      m.tets.push_back({index.at(t[0]), index.at(t[1]), index.at(t[2]), index.at(t[3])});
      m.level.push_back(levels_out_[i]);
    }
    return std::move(out_);
  }

  const Shape& shape_;
  const Fit& fit_;
  const d3::Graph& g_;
  const StuffOptions& options_;
  std::vector<d3::Tet> tets_;
  std::map<d3::Point, double> value_;
  std::map<std::pair<d3::Point, d3::Point>, detail::Cut> cuts_;
  std::map<d3::Point, std::vector<d3::Point>> at_;  ///< the other ends of the cut edges at a vertex
  std::map<d3::Point, Vec3> warped_;
  Stuffed out_;
};

}  // namespace

Stuffed stuff(const Shape& shape, const Fit& fit, const d3::Graph& g, const StuffOptions& options, PhaseTimes* times) {
  detail::PhaseClock clock(times);
  std::vector<d3::Tet> tets = d3::tetrahedra(g);
  clock.lap(&PhaseTimes::mesh);
  return ReferenceStuffer(shape, fit, g, options).run(std::move(tets), times);
}

}  // namespace bccmis::stuff
