// Isosurface stuffing on the graded BCC mesh (spec/stuffing.md S2-S13).
#include "bccmis/stuff/stuff.h"

#include <gmpxx.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "bccmis/apps/balance3.h"
#include "bccmis/d3/point.h"

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

d3::Graph3 background(const Shape& shape, const Fit& fit, const StuffOptions& options) {
  d3::Graph3 g = d3::make_lattice(fit.size);
  const int L = fit.size.L;
  // S3: refine while some leaf passes the test; each pass over a snapshot of C.
  for (bool changed = true; changed;) {
    changed = false;
    const std::vector<Point3> cells(g.C.begin(), g.C.end());
    for (const Point3& c : cells) {
      if (!g.is_center(c)) continue;  // refined by the cascade earlier in this pass
      const int l = g.level_of(c);
      if (l >= L) continue;
      const double r = 0.5 * static_cast<double>(d3::cell_side(fit.size, l)) * fit.scale;
      const bool near = std::abs(shape.signed_distance(fit.to_space(c))) <= std::sqrt(3.0) * r + 4 * fit.h;
      if (near || l < options.min_level) {
        d3::refine_balanced(g, c);
        changed = true;
      }
    }
  }
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

/// A vertex of the output (S8's key): a lattice vertex p is (p, p), the cut
/// point on lattice edge xy is (min(x, y), max(x, y)).
struct VKey {
  Point3 a, b;
  bool is_cut() const { return !(a == b); }
  friend auto operator<=>(const VKey&, const VKey&) = default;
};
VKey lattice_key(const Point3& p) { return {p, p}; }
VKey cut_key(const Point3& x, const Point3& y) { return x < y ? VKey{x, y} : VKey{y, x}; }

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

struct Cut {
  double t = 0;  ///< from the edge's smaller end
  Vec3 pos{};
  bool removed = false;
};

class Stuffer {
 public:
  Stuffer(const Shape& shape, const Fit& fit, const d3::Graph3& g, const StuffOptions& options)
      : shape_(shape), fit_(fit), g_(g), options_(options) {}

  Stuffed run() {
    tets_ = d3::tetrahedra(g_);
    out_.lattice_tetrahedra = tets_.size();
    evaluate();
    cut();
    warp();
    for (const d3::Tet& t : tets_) fill(t);
    return finish();
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

}  // namespace

Stuffed stuff(const Shape& shape, const Fit& fit, const d3::Graph3& g, const StuffOptions& options) {
  return Stuffer(shape, fit, g, options).run();
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
