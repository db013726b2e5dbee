// Isosurface stuffing on the graded BCC mesh (spec/stuffing.md S2-S13).
#include "bccmis/stuff/stuff.h"

#include <gmpxx.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <ostream>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "bccmis/balance.h"
#include "bccmis/d3/lattice.h"
#include "bccmis/d3/point.h"
#include "bccmis/fast/mesh3.h"

namespace bccmis::stuff {

using d3::Point3;

// ---------------------------------------------------------------------------
// S2, S3: the background lattice

Fit fit_lattice(const Bounds& box, const StuffOptions& options) {
  Vec3 extent{};
  for (std::size_t i = 0; i < 3; ++i) {
    extent[i] = box.hi[i] - box.lo[i];
    if (!std::isfinite(box.lo[i]) || !std::isfinite(box.hi[i]) || extent[i] < 0)
      throw ShapeError("the shape's bounding box is empty or not finite");
  }
  const double E = std::max({extent[0], extent[1], extent[2]});
  if (!(E > 0)) throw ShapeError("the shape's bounding box has no extent");
  if (options.cells < 1) throw ShapeError("--cells must be at least 1");
  int L = options.max_level;
  if (options.size) {
    // S2: the smallest L with N 2^L h >= E + 10h.
    const double h = *options.size;
    if (!(h > 0) || !std::isfinite(h)) throw ShapeError("--size must be positive");
    L = 0;
    while (static_cast<double>(options.cells) * std::ldexp(h, L) < E + 10 * h) {
      if (++L > 20) throw ShapeError("--size is too small for the shape: it needs more than 20 levels");
    }
  }
  if (L < 0 || L > 20) throw ShapeError("--max-level must be in [0, 20]");
  if (options.min_level < 0 || options.min_level > L)
    throw ShapeError("--min-level must be in [0, max level " + std::to_string(L) + "]");
  const double n2L = std::ldexp(static_cast<double>(options.cells), L);
  if (n2L <= 10)
    throw ShapeError("--cells x 2^max-level must exceed 10 (the margin of 5 finest cells on each side); it is " +
                     std::to_string(static_cast<long long>(n2L)));
  Fit fit;
  const double S = E / (options.cells - 10.0 / std::ldexp(1.0, L));
  fit.h = std::ldexp(S, -L);
  std::int64_t counts[3];
  for (std::size_t i = 0; i < 3; ++i) {
    const double need = extent[i] + 10 * fit.h;
    counts[i] = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(need / S - 1e-12)));
    fit.origin[i] = 0.5 * (box.lo[i] + box.hi[i]) - 0.5 * static_cast<double>(counts[i]) * S;
  }
  fit.size = d3::LatticeSize3{counts[0], counts[1], counts[2], L};
  fit.scale = std::ldexp(S, -(L + 1));
  return fit;
}

namespace {

/// S3 on either lattice: the same passes, the same refines in the same order
/// (every pass visits the leaves of its start in sorted order), so the same
/// leaf set on Graph3 and fast::Lattice3.
template <class G>
void refine_near(const Shape& shape, const Fit& fit, const StuffOptions& options, G& g) {
  const int L = fit.size.L;
  std::vector<Point3> snapshot;
  for (bool changed = true; changed;) {
    changed = false;
    {
      const auto& cs = cells(g);  // sorted on both lattices
      snapshot.assign(cs.begin(), cs.end());
    }
    for (const Point3& c : snapshot) {
      if (!is_center(g, c)) continue;  // refined by the cascade earlier in this pass
      const int l = level_of(g, c);
      if (l >= L) continue;
      const double r = 0.5 * static_cast<double>(d3::cell_side(fit.size, l)) * fit.scale;
      const bool near = shape.distance(fit.to_space(c)) <= std::sqrt(3.0) * r + 4 * fit.h;
      if (near || l < options.min_level) {
        d3::refine_balanced(g, c);
        changed = true;
      }
    }
  }
}

}  // namespace

d3::Graph3 background(const Shape& shape, const Fit& fit, const StuffOptions& options) {
  d3::Graph3 g = d3::make_lattice(fit.size);
  refine_near(shape, fit, options, g);
  return g;
}

fast::Lattice3 background_fast(const Shape& shape, const Fit& fit, const StuffOptions& options) {
  fast::Lattice3 g(fit.size);
  refine_near(shape, fit, options, g);
  return g;
}

// ---------------------------------------------------------------------------
// S12: exact orientation

int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
  const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
  const double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
  const double bc = bdx * cdy - cdx * bdy, ca = cdx * ady - adx * cdy, ab = adx * bdy - bdx * ady;
  // det[a-d, b-d, c-d] = -det[b-a, c-a, d-a] ... both are the orientation of
  // (a, b, c, d) up to the sign fixed below: det[b-a, c-a, d-a] = -det[a-d, b-d, c-d].
  const double det = adz * bc + bdz * ca + cdz * ab;
  const double permanent = (std::abs(bdx * cdy) + std::abs(cdx * bdy)) * std::abs(adz) +
                           (std::abs(cdx * ady) + std::abs(adx * cdy)) * std::abs(bdz) +
                           (std::abs(adx * bdy) + std::abs(bdx * ady)) * std::abs(cdz);
  // Shewchuk's bound for this expression (o3derrboundA), with eps = 2^-53.
  constexpr double eps = std::numeric_limits<double>::epsilon() / 2;
  constexpr double bound = (7.0 + 56.0 * eps) * eps;
  if (det > bound * permanent) return -1;
  if (-det > bound * permanent) return 1;
  // Exactly: the translations and products of doubles are rationals.
  auto q = [](double x) { return mpq_class(x); };
  const mpq_class ex = q(a[0]) - q(d[0]), fx = q(b[0]) - q(d[0]), gx = q(c[0]) - q(d[0]);
  const mpq_class ey = q(a[1]) - q(d[1]), fy = q(b[1]) - q(d[1]), gy = q(c[1]) - q(d[1]);
  const mpq_class ez = q(a[2]) - q(d[2]), fz = q(b[2]) - q(d[2]), gz = q(c[2]) - q(d[2]);
  const mpq_class exact = ez * (fx * gy - gx * fy) + fz * (gx * ey - ex * gy) + gz * (ex * fy - fx * ey);
  return -sgn(exact);
}

// ---------------------------------------------------------------------------
// S5-S9: cut points, warping, stencils

namespace {

std::int64_t length2(const Point3& p, const Point3& q) {
  const std::int64_t dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
  return dx * dx + dy * dy + dz * dz;
}

/// S4: the regular BCC tetrahedron of level L has squared edge lengths 4
/// (two long edges) and 3 (four short ones) in lattice coordinates.
void check_regular(const d3::Tet& t, int L) {
  int longs = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const std::int64_t l2 = length2(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>(j)]);
      if (l2 == 4)
        ++longs;
      else if (l2 != 3)
        throw std::logic_error("stuff: a tetrahedron at " + d3::to_string(t[0]) +
                               " with a cut edge or a warped vertex is not a regular BCC tetrahedron of level " +
                               std::to_string(L) + " (spec/stuffing.md S4)");
    }
  if (longs != 2) throw std::logic_error("stuff: a tetrahedron at " + d3::to_string(t[0]) + " is not regular (S4)");
}

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The reference path: the stuffing of spec/stuffing.md written on ordered
// maps keyed by lattice points, the oracle of the flat path below
// (tests/stuff/stuffing_fast_test.cpp).
namespace reference_path {

/// A vertex of the output (S8's key): a lattice vertex p is (p, p), the cut
/// point on lattice edge xy is (min(x, y), max(x, y)).
struct VKey {
  Point3 a, b;
  bool is_cut() const { return !(a == b); }
  friend auto operator<=>(const VKey&, const VKey&) = default;
};
VKey lattice_key(const Point3& p) { return {p, p}; }
VKey cut_key(const Point3& x, const Point3& y) { return x < y ? VKey{x, y} : VKey{y, x}; }

struct Cut {
  double t = 0;  ///< from the edge's smaller end
  Vec3 pos{};
  bool removed = false;
};

class ReferenceStuffer {
 public:
  ReferenceStuffer(const Shape& shape, const Fit& fit, const d3::Graph3& g, const StuffOptions& options)
      : shape_(shape), fit_(fit), g_(g), options_(options) {}

  Stuffed run(std::vector<d3::Tet> tets, PhaseTimes* times) {
    auto t0 = Clock::now();
    tets_ = std::move(tets);
    out_.lattice_tetrahedra = tets_.size();
    evaluate();
    cut();
    if (times) times->cut = seconds_since(t0);
    t0 = Clock::now();
    warp();
    if (times) times->warp = seconds_since(t0);
    t0 = Clock::now();
    for (const d3::Tet& t : tets_) fill(t);
    Stuffed s = finish();
    if (times) times->stencils = seconds_since(t0);
    return s;
  }

 private:
  double f(const Point3& p) const { return value_.at(p); }
  Vec3 pos(const VKey& k) const {
    if (k.is_cut()) return cuts_.at({k.a, k.b}).pos;
    const auto it = warped_.find(k.a);
    return it != warped_.end() ? it->second : fit_.to_space(k.a);
  }

  void evaluate() {
    for (const d3::Tet& t : tets_)
      for (const Point3& p : t)
        if (!value_.count(p)) value_.emplace(p, shape_.signed_distance(fit_.to_space(p)));
  }

  // S5
  void cut() {
    for (const d3::Tet& t : tets_) {
      bool has_cut = false;
      for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j) {
          Point3 x = t[i], y = t[j];
          if (y < x) std::swap(x, y);
          const double fx = f(x), fy = f(y);
          if (!((fx < 0 && fy > 0) || (fx > 0 && fy < 0))) continue;
          has_cut = true;
          if (cuts_.count({x, y})) continue;
          const Vec3 px = fit_.to_space(x), py = fit_.to_space(y);
          const double s = std::clamp(shape_.crossing(px, py), 0.0, 1.0);
          Cut c;
          c.t = s;
          for (std::size_t k = 0; k < 3; ++k) c.pos[k] = px[k] + s * (py[k] - px[k]);
          cuts_.emplace(std::make_pair(x, y), c);
          at_[x].push_back(y);
          at_[y].push_back(x);
        }
      if (has_cut) check_regular(t, fit_.size.L);
    }
  }

  bool same_kind(const Point3& p, const Point3& q) const { return g_.is_center(p) == g_.is_center(q); }

  // S6, in increasing position order.
  void warp() {
    for (auto& [v, others] : at_) {
      std::sort(others.begin(), others.end());
      const Point3* best = nullptr;
      double best_distance = 0;
      for (const Point3& w : others) {
        const auto key = v < w ? std::make_pair(v, w) : std::make_pair(w, v);
        const Cut& c = cuts_.at(key);
        if (c.removed) continue;
        const double from_v = v < w ? c.t : 1 - c.t;
        const double alpha = same_kind(v, w) ? options_.alpha_long : options_.alpha_short;
        if (!(from_v < alpha)) continue;
        const double distance = from_v * std::sqrt(static_cast<double>(length2(v, w)));
        if (!best || distance < best_distance) best = &w, best_distance = distance;
      }
      if (!best) continue;
      const Point3 w = *best;
      warped_[v] = cuts_.at(v < w ? std::make_pair(v, w) : std::make_pair(w, v)).pos;
      value_[v] = 0;
      for (const Point3& x : others) cuts_.at(v < x ? std::make_pair(v, x) : std::make_pair(x, v)).removed = true;
    }
    out_.warped = warped_.size();
    for (const auto& [k, c] : cuts_) out_.cut_points += c.removed ? 0 : 1;
  }

  /// The angle at p between the directions to x and y.
  static double angle(const Vec3& p, const Vec3& x, const Vec3& y) {
    const Vec3 u{x[0] - p[0], x[1] - p[1], x[2] - p[2]}, v{y[0] - p[0], y[1] - p[1], y[2] - p[2]};
    const double c = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) /
                     std::sqrt((u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    return std::acos(std::clamp(c, -1.0, 1.0));
  }

  // S8: the diagonal of the face quadrilateral (a, b, c_bt, c_at) as a pair of keys.
  std::pair<VKey, VKey> face_diagonal(const Point3& a, const Point3& b, const Point3& t) const {
    const VKey ka = lattice_key(a), kb = lattice_key(b), cat = cut_key(a, t), cbt = cut_key(b, t);
    const std::int64_t la = length2(a, t), lb = length2(b, t);
    if (la > lb) return {cat, kb};
    if (lb > la) return {cbt, ka};
    // Equal: the Delaunay diagonal of the planar quadrilateral (a, b, c_bt,
    // c_at), computed from the ends in position order so that both
    // tetrahedra at the face compute the same; a tie by the smallest key.
    if (b < a) return face_diagonal(b, a, t);
    const Vec3 pa = pos(ka), pb = pos(kb), pbt = pos(cbt), pat = pos(cat);
    const double at_b = angle(pb, pa, pbt), at_cat = angle(pat, pbt, pa);
    const double at_a = angle(pa, pat, pb), at_cbt = angle(pbt, pb, pat);
    if (at_b + at_cat < at_a + at_cbt) return {ka, cbt};
    if (at_b + at_cat > at_a + at_cbt) return {kb, cat};
    const VKey m = std::min({ka, kb, cat, cbt});
    if (m == ka || m == cbt) return {ka, cbt};
    return {kb, cat};
  }

  void emit(const std::array<VKey, 4>& t, int level) {
    std::array<VKey, 4> v = t;
    const int o = orientation(pos(v[0]), pos(v[1]), pos(v[2]), pos(v[3]));
    if (o == 0) throw std::logic_error("stuff: a flat output tetrahedron near " + d3::to_string(v[0].a));
    if (o < 0) std::swap(v[2], v[3]);
    tets_out_.push_back({v, level});
  }

  /// The pyramid with apex x over the quadrilateral q (cyclic), split by the
  /// diagonal d (two opposite corners of q).
  void pyramid(const VKey& x, const std::array<VKey, 4>& q, const std::pair<VKey, VKey>& d, int level) {
    const bool d02 = (d.first == q[0] && d.second == q[2]) || (d.first == q[2] && d.second == q[0]);
    if (d02) {
      emit({x, q[0], q[1], q[2]}, level);
      emit({x, q[0], q[2], q[3]}, level);
    } else {
      emit({x, q[1], q[2], q[3]}, level);
      emit({x, q[1], q[3], q[0]}, level);
    }
  }

  /// S9: the prism A0 A1 A2 - B0 B1 B2 with the diagonals d[i] of
  /// Qi = (Ai, Ai+1, Bi+1, Bi): true for Ai Bi+1, false for Ai+1 Bi.
  void prism(const std::array<VKey, 3>& A, const std::array<VKey, 3>& B, const std::array<bool, 3>& d, int level) {
    if (d[0] == d[1] && d[1] == d[2]) throw std::logic_error("stuff: cyclic prism diagonals (S9)");
    for (std::size_t i = 0; i < 3; ++i) {
      const std::size_t n = (i + 1) % 3, p = (i + 2) % 3;  // i+1, i-1
      const bool two_at_A = d[i] && !d[p], two_at_B = !d[i] && d[p];
      if (!two_at_A && !two_at_B) continue;
      // Q(i+1) = (A n, A p, B p, B n), its diagonal A n B p (d[n]) or A p B n.
      const std::array<VKey, 4> q{A[n], A[p], B[p], B[n]};
      const std::pair<VKey, VKey> diag = d[n] ? std::make_pair(A[n], B[p]) : std::make_pair(A[p], B[n]);
      if (two_at_A) {
        emit({A[i], B[0], B[1], B[2]}, level);
        pyramid(A[i], q, diag, level);
      } else {
        emit({B[i], A[0], A[1], A[2]}, level);
        pyramid(B[i], q, diag, level);
      }
      return;
    }
  }

  /// d for quadrilateral (X0, X1, Y1, Y0): true when `diag` joins X0 and Y1.
  static bool diag_bit(const std::pair<VKey, VKey>& diag, const VKey& x0, const VKey& y1) {
    return (diag.first == x0 && diag.second == y1) || (diag.first == y1 && diag.second == x0);
  }

  double min_angle(const std::vector<std::array<VKey, 4>>& tets) const {
    double m = 180;
    for (const auto& t : tets)
      for (const double a : d3::dihedral_angles(std::array<Vec3, 4>{pos(t[0]), pos(t[1]), pos(t[2]), pos(t[3])}))
        m = std::min(m, a);
    return m;
  }

  // S7
  void fill(const d3::Tet& t) {
    std::vector<Point3> neg, zero, plus;
    bool warped = false;
    for (const Point3& p : t) {
      const double v = f(p);
      (v < 0 ? neg : v > 0 ? plus : zero).push_back(p);
      warped = warped || warped_.count(p);
    }
    if (warped) check_regular(t, fit_.size.L);
    const int level = g_.level_of(t[0]);
    const auto L = [](const Point3& p) { return lattice_key(p); };
    const auto C = [](const Point3& x, const Point3& y) { return cut_key(x, y); };
    if (plus.empty()) {
      // All four zero: nothing (the surface passes through every vertex, so
      // the tetrahedron is a sliver along it; S7).
      if (!neg.empty()) emit({L(t[0]), L(t[1]), L(t[2]), L(t[3])}, level);
      return;
    }
    if (neg.empty()) return;
    const std::size_t n = neg.size(), z = zero.size();
    if (n == 1 && z == 0) {
      const Point3& a = neg[0];
      emit({L(a), C(a, plus[0]), C(a, plus[1]), C(a, plus[2])}, level);
    } else if (n == 1 && z == 1) {
      const Point3& a = neg[0];
      emit({L(a), L(zero[0]), C(a, plus[0]), C(a, plus[1])}, level);
    } else if (n == 1 && z == 2) {
      const Point3& a = neg[0];
      emit({L(a), L(zero[0]), L(zero[1]), C(a, plus[0])}, level);
    } else if (n == 2 && z == 1) {
      const Point3 &a = neg[0], &b = neg[1], &p = plus[0];
      pyramid(L(zero[0]), {L(a), L(b), C(b, p), C(a, p)}, face_diagonal(a, b, p), level);
    } else if (n == 3) {
      // A = (a, b, c), B = (c_ap, c_bp, c_cp); Qi lies in the face (Ai, Ai+1, p).
      const Point3& p = plus[0];
      std::array<VKey, 3> A, B;
      std::array<bool, 3> d{};
      for (std::size_t i = 0; i < 3; ++i) A[i] = L(neg[i]), B[i] = C(neg[i], p);
      for (std::size_t i = 0; i < 3; ++i)
        d[i] = diag_bit(face_diagonal(neg[i], neg[(i + 1) % 3], p), A[i], B[(i + 1) % 3]);
      prism(A, B, d, level);
    } else {
      // 2 0 2: A = (a, c_ap, c_aq), B = (b, c_bp, c_bq); Q0 in face (a, b, p),
      // Q2 in face (a, b, q), Q1 = (c_ap, c_aq, c_bq, c_bp) inside, free.
      const Point3 &a = neg[0], &b = neg[1], &p = plus[0], &q = plus[1];
      const std::array<VKey, 3> A{L(a), C(a, p), C(a, q)}, B{L(b), C(b, p), C(b, q)};
      std::array<bool, 3> d{};
      d[0] = diag_bit(face_diagonal(a, b, p), A[0], B[1]);
      d[2] = diag_bit(face_diagonal(a, b, q), A[2], B[0]);
      if (d[0] != d[2]) {
        // Both choices are acyclic: the one with the larger smallest angle.
        const std::size_t before = tets_out_.size();
        double best = -1;
        bool best_d1 = false;
        for (const bool d1 : {false, true}) {
          d[1] = d1;
          prism(A, B, d, level);
          std::vector<std::array<VKey, 4>> made;
          for (std::size_t i = before; i < tets_out_.size(); ++i) made.push_back(tets_out_[i].first);
          tets_out_.resize(before);
          const double m = min_angle(made);
          if (m > best) best = m, best_d1 = d1;
        }
        d[1] = best_d1;
      } else {
        d[1] = !d[0];
      }
      prism(A, B, d, level);
    }
  }

  Stuffed finish() {
    std::map<VKey, std::uint32_t> index;
    for (const auto& [t, level] : tets_out_)
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
    for (const auto& [t, level] : tets_out_) {
      m.tets.push_back({index.at(t[0]), index.at(t[1]), index.at(t[2]), index.at(t[3])});
      m.level.push_back(level);
    }
    return std::move(out_);
  }

  const Shape& shape_;
  const Fit& fit_;
  const d3::Graph3& g_;
  const StuffOptions& options_;
  std::vector<d3::Tet> tets_;
  std::map<Point3, double> value_;
  std::map<std::pair<Point3, Point3>, Cut> cuts_;
  std::map<Point3, std::vector<Point3>> at_;  ///< the other ends of the cut edges at a vertex
  std::map<Point3, Vec3> warped_;
  std::vector<std::pair<std::array<VKey, 4>, int>> tets_out_;
  Stuffed out_;
};

}  // namespace reference_path

// The flat path: the same decisions in the same order on arrays indexed by
// the lattice vertices numbered in position order.
namespace flat_path {

/// A vertex of the output (S8's key) on the lattice vertices numbered in
/// position order: lattice vertex i is (i, i), the cut point on lattice edge
/// ij is (min(i, j), max(i, j)), packed as high << 32 | low. The numbering
/// keeps the order of positions, so the packed keys sort as S8's pairs of
/// points.
using VKey = std::uint64_t;
VKey lattice_key(std::uint32_t i) { return (VKey{i} << 32) | i; }
VKey cut_key(std::uint32_t i, std::uint32_t j) { return i < j ? (VKey{i} << 32) | j : (VKey{j} << 32) | i; }
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

struct Cut {
  double t = 0;  ///< from the edge's smaller end
  Vec3 pos{};
  bool removed = false;
};

/// S5-S9 on the graded mesh of a lattice G (d3::Graph3 or fast::Lattice3,
/// through the vocabulary: is_center, level_of). The lattice's vertices are
/// numbered in position order and every per-vertex datum is an array.
template <class G>
class Stuffer {
 public:
  Stuffer(const Shape& shape, const Fit& fit, const G& g, const StuffOptions& options)
      : shape_(shape), fit_(fit), g_(g), options_(options) {}

  /// Also report, for stuff_part(), each output vertex's key as lattice
  /// points and where each lattice tetrahedron's output tetrahedra begin.
  void record(std::vector<std::array<Point3, 2>>* keys, std::vector<std::uint32_t>* begin) {
    keys_ = keys;
    begin_ = begin;
  }

  Stuffed run(std::vector<d3::Tet> tets, PhaseTimes* times) {
    owned_ = std::move(tets);
    return run(std::span<const d3::Tet>(owned_), times);
  }

  /// The same on tetrahedra the caller keeps.
  Stuffed run(std::span<const d3::Tet> tets, PhaseTimes* times) {
    auto t0 = Clock::now();
    tets_ = tets;
    out_.lattice_tetrahedra = tets_.size();
    number();
    evaluate();
    cut();
    if (times) times->cut = seconds_since(t0);
    t0 = Clock::now();
    warp();
    if (times) times->warp = seconds_since(t0);
    t0 = Clock::now();
    if (begin_) begin_->reserve(tets_.size() + 1);
    for (std::size_t i = 0; i < tets_.size(); ++i) {
      if (begin_) begin_->push_back(static_cast<std::uint32_t>(tets_out_.size()));
      fill(i);
    }
    if (begin_) begin_->push_back(static_cast<std::uint32_t>(tets_out_.size()));
    Stuffed s = finish();
    if (times) times->stencils = seconds_since(t0);
    return s;
  }

 private:
  using Ids = std::array<std::uint32_t, 4>;

  Vec3 pos(VKey k) const { return is_cut(k) ? cuts_[cut_index_.find(k)].pos : pos_[first(k)]; }

  // The lattice vertices of the mesh in position order, the tetrahedra on
  // them: ids in order of first use through a hash table, then renumbered by
  // rank of position.
  void number() {
    // The vertices are centers, nodes and hull points (centers of the
    // domain's faces, at most one per leaf): load at most 1/2.
    const std::size_t most = std::min(2 * cell_count(g_) + node_count(g_), 4 * tets_.size());
    std::size_t slots = 16;
    while (slots < 2 * most) slots *= 2;
    std::vector<std::uint32_t> table(slots, EdgeTable::kNone);
    const auto hash = [&](const Point3& p) {
      const std::uint64_t h = static_cast<std::uint64_t>(p.x) * 0x9E3779B97F4A7C15ull ^
                              static_cast<std::uint64_t>(p.y) * 0xC2B2AE3D27D4EB4Full ^
                              static_cast<std::uint64_t>(p.z) * 0x165667B19E3779F9ull;
      return static_cast<std::size_t>(h ^ (h >> 29)) & (slots - 1);
    };
    ids_.reserve(tets_.size());
    for (const d3::Tet& t : tets_) {
      Ids ids{};
      for (std::size_t i = 0; i < 4; ++i) {
        std::size_t k = hash(t[i]);
        while (table[k] != EdgeTable::kNone && !(points_[table[k]] == t[i])) k = (k + 1) & (slots - 1);
        if (table[k] == EdgeTable::kNone) {
          table[k] = static_cast<std::uint32_t>(points_.size());
          points_.push_back(t[i]);
        }
        ids[i] = table[k];
      }
      ids_.push_back(ids);
    }
    std::vector<std::uint32_t> order(points_.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return points_[a] < points_[b]; });
    std::vector<std::uint32_t> rank(points_.size());
    std::vector<Point3> sorted(points_.size());
    for (std::uint32_t r = 0; r < order.size(); ++r) rank[order[r]] = r, sorted[r] = points_[order[r]];
    points_ = std::move(sorted);
    for (Ids& ids : ids_)
      for (std::uint32_t& i : ids) i = rank[i];
    level_.assign(points_.size(), -1);
  }

  void evaluate() {
    value_.resize(points_.size());
    pos_.resize(points_.size());
    for (std::size_t i = 0; i < points_.size(); ++i) {
      pos_[i] = fit_.to_space(points_[i]);
      value_[i] = shape_.side(pos_[i]);  // S5: only the sign enters
    }
  }

  // S5
  void cut() {
    cut_index_.reserve(points_.size() / 4);
    for (std::size_t ti = 0; ti < tets_.size(); ++ti) {
      const Ids& t = ids_[ti];
      bool has_cut = false;
      for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j) {
          const std::uint32_t x = std::min(t[i], t[j]), y = std::max(t[i], t[j]);
          const double fx = value_[x], fy = value_[y];
          if (!((fx < 0 && fy > 0) || (fx > 0 && fy < 0))) continue;
          has_cut = true;
          const VKey k = cut_key(x, y);
          if (cut_index_.find(k) != EdgeTable::kNone) continue;
          const Vec3 &px = pos_[x], &py = pos_[y];
          const double s = std::clamp(shape_.crossing(px, py), 0.0, 1.0);
          Cut c;
          c.t = s;
          for (std::size_t d = 0; d < 3; ++d) c.pos[d] = px[d] + s * (py[d] - px[d]);
          cut_index_.insert(k, static_cast<std::uint32_t>(cuts_.size()));
          cuts_.push_back(c);
          edges_.push_back({x, y});
          ends_.push_back({x, y});
          ends_.push_back({y, x});
        }
      if (has_cut) check_regular(tets_[ti], fit_.size.L);
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
        const Cut& c = cuts_[cut_index_.find(cut_key(v, w))];
        if (c.removed) continue;
        const double from_v = v < w ? c.t : 1 - c.t;
        const bool same_kind = v_center == is_center(g_, points_[w]);
        const double alpha = same_kind ? options_.alpha_long : options_.alpha_short;
        if (!(from_v < alpha)) continue;
        const double distance = from_v * std::sqrt(static_cast<double>(length2(points_[v], points_[w])));
        if (best == EdgeTable::kNone || distance < best_distance) best = w, best_distance = distance;
      }
      if (best == EdgeTable::kNone) continue;
      pos_[v] = cuts_[cut_index_.find(cut_key(v, best))].pos;
      warped_[v] = 1;
      value_[v] = 0;
      ++out_.warped;
      for (std::size_t i = b; i < e; ++i) cuts_[cut_index_.find(cut_key(v, ends_[i].second))].removed = true;
    }
    for (const Cut& c : cuts_) out_.cut_points += c.removed ? 0 : 1;
  }

  /// The angle at p between the directions to x and y.
  static double angle(const Vec3& p, const Vec3& x, const Vec3& y) {
    const Vec3 u{x[0] - p[0], x[1] - p[1], x[2] - p[2]}, v{y[0] - p[0], y[1] - p[1], y[2] - p[2]};
    const double c = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) /
                     std::sqrt((u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    return std::acos(std::clamp(c, -1.0, 1.0));
  }

  // S8: the diagonal of the face quadrilateral (a, b, c_bt, c_at) as a pair of keys.
  std::pair<VKey, VKey> face_diagonal(std::uint32_t a, std::uint32_t b, std::uint32_t t) const {
    const VKey ka = lattice_key(a), kb = lattice_key(b), cat = cut_key(a, t), cbt = cut_key(b, t);
    const std::int64_t la = length2(points_[a], points_[t]), lb = length2(points_[b], points_[t]);
    if (la > lb) return {cat, kb};
    if (lb > la) return {cbt, ka};
    // Equal: the Delaunay diagonal of the planar quadrilateral (a, b, c_bt,
    // c_at), computed from the ends in position order so that both
    // tetrahedra at the face compute the same; a tie by the smallest key.
    if (b < a) return face_diagonal(b, a, t);
    const Vec3 pa = pos(ka), pb = pos(kb), pbt = pos(cbt), pat = pos(cat);
    const double at_b = angle(pb, pa, pbt), at_cat = angle(pat, pbt, pa);
    const double at_a = angle(pa, pat, pb), at_cbt = angle(pbt, pb, pat);
    if (at_b + at_cat < at_a + at_cbt) return {ka, cbt};
    if (at_b + at_cat > at_a + at_cbt) return {kb, cat};
    const VKey m = std::min({ka, kb, cat, cbt});
    if (m == ka || m == cbt) return {ka, cbt};
    return {kb, cat};
  }

  void emit(const std::array<VKey, 4>& t, int level) {
    std::array<VKey, 4> v = t;
    const int o = orientation(pos(v[0]), pos(v[1]), pos(v[2]), pos(v[3]));
    if (o == 0) throw std::logic_error("stuff: a flat output tetrahedron near " + d3::to_string(points_[first(v[0])]));
    if (o < 0) std::swap(v[2], v[3]);
    tets_out_.push_back(v);
    levels_out_.push_back(level);
  }

  /// The pyramid with apex x over the quadrilateral q (cyclic), split by the
  /// diagonal d (two opposite corners of q).
  void pyramid(VKey x, const std::array<VKey, 4>& q, const std::pair<VKey, VKey>& d, int level) {
    const bool d02 = (d.first == q[0] && d.second == q[2]) || (d.first == q[2] && d.second == q[0]);
    if (d02) {
      emit({x, q[0], q[1], q[2]}, level);
      emit({x, q[0], q[2], q[3]}, level);
    } else {
      emit({x, q[1], q[2], q[3]}, level);
      emit({x, q[1], q[3], q[0]}, level);
    }
  }

  /// S9: the prism A0 A1 A2 - B0 B1 B2 with the diagonals d[i] of
  /// Qi = (Ai, Ai+1, Bi+1, Bi): true for Ai Bi+1, false for Ai+1 Bi.
  void prism(const std::array<VKey, 3>& A, const std::array<VKey, 3>& B, const std::array<bool, 3>& d, int level) {
    if (d[0] == d[1] && d[1] == d[2]) throw std::logic_error("stuff: cyclic prism diagonals (S9)");
    for (std::size_t i = 0; i < 3; ++i) {
      const std::size_t n = (i + 1) % 3, p = (i + 2) % 3;  // i+1, i-1
      const bool two_at_A = d[i] && !d[p], two_at_B = !d[i] && d[p];
      if (!two_at_A && !two_at_B) continue;
      // Q(i+1) = (A n, A p, B p, B n), its diagonal A n B p (d[n]) or A p B n.
      const std::array<VKey, 4> q{A[n], A[p], B[p], B[n]};
      const std::pair<VKey, VKey> diag = d[n] ? std::make_pair(A[n], B[p]) : std::make_pair(A[p], B[n]);
      if (two_at_A) {
        emit({A[i], B[0], B[1], B[2]}, level);
        pyramid(A[i], q, diag, level);
      } else {
        emit({B[i], A[0], A[1], A[2]}, level);
        pyramid(B[i], q, diag, level);
      }
      return;
    }
  }

  /// d for quadrilateral (X0, X1, Y1, Y0): true when `diag` joins X0 and Y1.
  static bool diag_bit(const std::pair<VKey, VKey>& diag, VKey x0, VKey y1) {
    return (diag.first == x0 && diag.second == y1) || (diag.first == y1 && diag.second == x0);
  }

  /// The smallest dihedral angle of the tetrahedra emitted from `from` on.
  double min_angle(std::size_t from) const {
    double m = 180;
    for (std::size_t i = from; i < tets_out_.size(); ++i) {
      const auto& t = tets_out_[i];
      for (const double a : d3::dihedral_angles(std::array<Vec3, 4>{pos(t[0]), pos(t[1]), pos(t[2]), pos(t[3])}))
        m = std::min(m, a);
    }
    return m;
  }

  // S7
  void fill(std::size_t ti) {
    const Ids& t = ids_[ti];
    std::array<std::uint32_t, 4> neg{}, zero{}, plus{};
    std::size_t n = 0, z = 0, np = 0;
    bool warped = false;
    for (const std::uint32_t p : t) {
      const double v = value_[p];
      if (v < 0)
        neg[n++] = p;
      else if (v > 0)
        plus[np++] = p;
      else
        zero[z++] = p;
      warped = warped || warped_[p];
    }
    if (warped) check_regular(tets_[ti], fit_.size.L);
    const auto L = [](std::uint32_t p) { return lattice_key(p); };
    const auto C = [](std::uint32_t x, std::uint32_t y) { return cut_key(x, y); };
    if (np == 0) {
      // All four zero: nothing (the surface passes through every vertex, so
      // the tetrahedron is a sliver along it; S7).
      if (n != 0) emit({L(t[0]), L(t[1]), L(t[2]), L(t[3])}, level(ti));
      return;
    }
    if (n == 0) return;
    const int level = this->level(ti);
    if (n == 1 && z == 0) {
      const std::uint32_t a = neg[0];
      emit({L(a), C(a, plus[0]), C(a, plus[1]), C(a, plus[2])}, level);
    } else if (n == 1 && z == 1) {
      const std::uint32_t a = neg[0];
      emit({L(a), L(zero[0]), C(a, plus[0]), C(a, plus[1])}, level);
    } else if (n == 1 && z == 2) {
      const std::uint32_t a = neg[0];
      emit({L(a), L(zero[0]), L(zero[1]), C(a, plus[0])}, level);
    } else if (n == 2 && z == 1) {
      const std::uint32_t a = neg[0], b = neg[1], p = plus[0];
      pyramid(L(zero[0]), {L(a), L(b), C(b, p), C(a, p)}, face_diagonal(a, b, p), level);
    } else if (n == 3) {
      // A = (a, b, c), B = (c_ap, c_bp, c_cp); Qi lies in the face (Ai, Ai+1, p).
      const std::uint32_t p = plus[0];
      std::array<VKey, 3> A{}, B{};
      std::array<bool, 3> d{};
      for (std::size_t i = 0; i < 3; ++i) A[i] = L(neg[i]), B[i] = C(neg[i], p);
      for (std::size_t i = 0; i < 3; ++i)
        d[i] = diag_bit(face_diagonal(neg[i], neg[(i + 1) % 3], p), A[i], B[(i + 1) % 3]);
      prism(A, B, d, level);
    } else {
      // 2 0 2: A = (a, c_ap, c_aq), B = (b, c_bp, c_bq); Q0 in face (a, b, p),
      // Q2 in face (a, b, q), Q1 = (c_ap, c_aq, c_bq, c_bp) inside, free.
      const std::uint32_t a = neg[0], b = neg[1], p = plus[0], q = plus[1];
      const std::array<VKey, 3> A{L(a), C(a, p), C(a, q)}, B{L(b), C(b, p), C(b, q)};
      std::array<bool, 3> d{};
      d[0] = diag_bit(face_diagonal(a, b, p), A[0], B[1]);
      d[2] = diag_bit(face_diagonal(a, b, q), A[2], B[0]);
      if (d[0] != d[2]) {
        // Both choices are acyclic: the one with the larger smallest angle.
        const std::size_t before = tets_out_.size();
        double best = -1;
        bool best_d1 = false;
        for (const bool d1 : {false, true}) {
          d[1] = d1;
          prism(A, B, d, level);
          const double m = min_angle(before);
          tets_out_.resize(before);
          levels_out_.resize(before);
          if (m > best) best = m, best_d1 = d1;
        }
        d[1] = best_d1;
      } else {
        d[1] = !d[0];
      }
      prism(A, B, d, level);
    }
  }

  /// The level of the leaf of tetrahedron ti (its vertex 0, spec/mesh3d.md),
  /// asked of the lattice once per leaf.
  int level(std::size_t ti) {
    int& l = level_[ids_[ti][0]];
    if (l < 0) l = level_of(g_, tets_[ti][0]);
    return l;
  }

  Stuffed finish() {
    // S8: the output vertices in key order: the lattice vertices used (keys
    // (i, i), in order of i) merged with the cut points used (in key order).
    std::vector<std::uint8_t> used_vertex(points_.size(), 0), used_cut(cuts_.size(), 0);
    for (const auto& t : tets_out_)
      for (const VKey k : t) {
        if (is_cut(k))
          used_cut[cut_index_.find(k)] = 1;
        else
          used_vertex[first(k)] = 1;
      }
    std::vector<VKey> cut_keys;
    for (std::size_t c = 0; c < cuts_.size(); ++c)
      if (used_cut[c]) cut_keys.push_back(cut_key(edges_[c].first, edges_[c].second));
    std::sort(cut_keys.begin(), cut_keys.end());
    std::vector<std::uint32_t> vertex_index(points_.size(), EdgeTable::kNone),
        cut_index(cuts_.size(), EdgeTable::kNone);
    d3::TetMeshF& m = out_.mesh;
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
    const auto index = [&](VKey k) { return is_cut(k) ? cut_index[cut_index_.find(k)] : vertex_index[first(k)]; };
    m.tets.reserve(tets_out_.size());
    for (const auto& t : tets_out_) m.tets.push_back({index(t[0]), index(t[1]), index(t[2]), index(t[3])});
    m.level = std::move(levels_out_);
    return std::move(out_);
  }

  const Shape& shape_;
  const Fit& fit_;
  const G& g_;
  const StuffOptions& options_;
  std::vector<d3::Tet> owned_;
  std::span<const d3::Tet> tets_;
  std::vector<Point3> points_;  ///< the lattice vertices of the mesh, sorted
  std::vector<Ids> ids_;        ///< tets_ on points_
  std::vector<double> value_;   ///< the sign of f (-1, 0, 1), 0 once warped
  std::vector<Vec3> pos_;       ///< in space, warped or not
  std::vector<std::uint8_t> warped_;
  std::vector<int> level_;  ///< of the leaves, -1 until asked
  std::vector<Cut> cuts_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges_;  ///< of cuts_, smaller end first
  EdgeTable cut_index_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends_;  ///< (v, w) for each cut edge vw, both ways
  std::vector<std::array<VKey, 4>> tets_out_;
  std::vector<int> levels_out_;
  Stuffed out_;
  std::vector<std::array<Point3, 2>>* keys_ = nullptr;
  std::vector<std::uint32_t>* begin_ = nullptr;
};

}  // namespace flat_path

}  // namespace

Stuffed stuff(const Shape& shape, const Fit& fit, const d3::Graph3& g, const StuffOptions& options, PhaseTimes* times) {
  const auto t0 = Clock::now();
  std::vector<d3::Tet> tets = d3::tetrahedra(g);
  if (times) times->mesh = seconds_since(t0);
  return reference_path::ReferenceStuffer(shape, fit, g, options).run(std::move(tets), times);
}

Stuffed stuff(const Shape& shape, const Fit& fit, const fast::Lattice3& g, const StuffOptions& options,
              PhaseTimes* times) {
  const auto t0 = Clock::now();
  std::vector<d3::Tet> tets = fast::tetrahedra(g);
  if (times) times->mesh = seconds_since(t0);
  return flat_path::Stuffer<fast::Lattice3>(shape, fit, g, options).run(std::move(tets), times);
}

StuffedPart stuff_part(const Shape& shape, const Fit& fit, const fast::Lattice3& g, const StuffOptions& options,
                       std::span<const d3::Tet> tets) {
  StuffedPart part;
  flat_path::Stuffer<fast::Lattice3> stuffer(shape, fit, g, options);
  stuffer.record(&part.keys, &part.begin);
  part.stuffed = stuffer.run(tets, nullptr);
  return part;
}

Stuffed stuff_shape(const Shape& shape, const StuffOptions& options, Impl impl, PhaseTimes* times) {
  const Fit fit = fit_lattice(shape.bounds(), options);
  const auto t0 = Clock::now();
  if (impl == Impl::reference) {
    const d3::Graph3 g = background(shape, fit, options);
    if (times) times->lattice = seconds_since(t0);
    return stuff(shape, fit, g, options, times);
  }
  const fast::Lattice3 g = background_fast(shape, fit, options);
  if (times) times->lattice = seconds_since(t0);
  return stuff(shape, fit, g, options, times);
}

// ---------------------------------------------------------------------------
// S11, S13: boundary, quality, surface writers

std::vector<std::array<std::uint32_t, 3>> boundary_triangles(const d3::TetMeshF& mesh) {
  // The face opposite v_i of a positive tetrahedron, outward.
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  std::map<std::array<std::uint32_t, 3>, std::pair<int, std::array<std::uint32_t, 3>>> seen;
  for (const auto& t : mesh.tets)
    for (const auto& f : kFaces) {
      const std::array<std::uint32_t, 3> tri{t[static_cast<std::size_t>(f[0])], t[static_cast<std::size_t>(f[1])],
                                             t[static_cast<std::size_t>(f[2])]};
      std::array<std::uint32_t, 3> key = tri;
      std::sort(key.begin(), key.end());
      auto& [count, oriented] = seen[key];
      ++count;
      oriented = tri;
    }
  std::vector<std::array<std::uint32_t, 3>> out;
  for (const auto& [key, entry] : seen)
    if (entry.first == 1) out.push_back(entry.second);
  return out;
}

namespace {
using Corner = std::tuple<double, double, double, std::uint8_t>;
using Canonical = std::pair<int, std::array<Corner, 4>>;
std::vector<Canonical> canonical(const d3::TetMeshF& m) {
  std::vector<Canonical> out;
  out.reserve(m.tets.size());
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    Canonical c{m.level.empty() ? 0 : m.level[t], {}};
    for (std::size_t i = 0; i < 4; ++i) {
      const std::uint32_t v = m.tets[t][i];
      c.second[i] = {m.vertices[v][0], m.vertices[v][1], m.vertices[v][2], m.kind.empty() ? 0 : m.kind[v]};
    }
    std::sort(c.second.begin(), c.second.end());
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}
}  // namespace

bool same_tetrahedra(const d3::TetMeshF& a, const d3::TetMeshF& b) {
  return a.tets.size() == b.tets.size() && canonical(a) == canonical(b);
}

StuffQuality quality(const d3::TetMeshF& mesh) {
  StuffQuality q;
  q.min_dihedral = mesh.tets.empty() ? 0 : 180;
  long double volume = 0;
  for (const auto& t : mesh.tets) {
    const std::array<Vec3, 4> p{mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]};
    bool small = false;
    for (const double a : d3::dihedral_angles(p)) {
      q.min_dihedral = std::min(q.min_dihedral, a);
      q.max_dihedral = std::max(q.max_dihedral, a);
      ++q.histogram[static_cast<std::size_t>(std::lround(a / 15.0))];
      small = small || a < 10;
    }
    q.below10 += small ? 1 : 0;
    long double e[3][3];
    for (int i = 0; i < 3; ++i)
      for (std::size_t k = 0; k < 3; ++k)
        e[i][k] = static_cast<long double>(p[static_cast<std::size_t>(i + 1)][k]) - static_cast<long double>(p[0][k]);
    volume += (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
               e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
              6;
  }
  q.volume = static_cast<double>(volume);
  q.boundary_triangles = boundary_triangles(mesh).size();
  return q;
}

namespace {

/// The vertices the triangles use, renumbered in order of first use.
std::pair<std::vector<std::uint32_t>, std::vector<std::array<std::uint32_t, 3>>> compact(
    const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& tris) {
  std::vector<std::uint32_t> used, renumber(mesh.vertices.size(), UINT32_MAX);
  std::vector<std::array<std::uint32_t, 3>> out;
  for (const auto& t : tris) {
    std::array<std::uint32_t, 3> r{};
    for (std::size_t i = 0; i < 3; ++i) {
      if (renumber[t[i]] == UINT32_MAX) renumber[t[i]] = static_cast<std::uint32_t>(used.size()), used.push_back(t[i]);
      r[i] = renumber[t[i]];
    }
    out.push_back(r);
  }
  return {used, out};
}

void write_coordinates(std::ostream& out, const Vec3& p) {
  char buf[96];
  char* it = buf;
  for (std::size_t i = 0; i < 3; ++i) {
    it = std::to_chars(it, buf + sizeof buf, p[i]).ptr;
    *it++ = i < 2 ? ' ' : '\n';
  }
  out.write(buf, it - buf);
}

}  // namespace

void write_off(std::ostream& out, const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& tris) {
  const auto [used, faces] = compact(mesh, tris);
  out << "OFF\n" << used.size() << ' ' << faces.size() << " 0\n";
  for (const std::uint32_t v : used) write_coordinates(out, mesh.vertices[v]);
  for (const auto& f : faces) out << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
}

void write_obj(std::ostream& out, const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& tris) {
  const auto [used, faces] = compact(mesh, tris);
  for (const std::uint32_t v : used) {
    out << "v ";
    write_coordinates(out, mesh.vertices[v]);
  }
  for (const auto& f : faces) out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
}

}  // namespace bccmis::stuff
