// The stencils of spec/stuffing.md S7-S9, written once for both stuffers
// (reference_stuffer.cpp on lattice points, flat_stuffer.cpp on position-
// ordered ids): which output tetrahedra fill a cut or warped lattice
// tetrahedron, the face diagonals of S8 and the prisms of S9.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "bccmis/d3/mesh.h"
#include "bccmis/d3/point.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff::detail {

/// S7-S9 over a stuffer `Derived` (CRTP) whose lattice vertices are `Vertex`
/// (ordered as their positions) and whose output vertices are `Key` (S8's
/// key: ordered as S8's pairs of points). Derived supplies
///   Key lattice_key(Vertex), Key cut_key(Vertex, Vertex): the keys of S8;
///   std::int64_t length2(Vertex, Vertex): squared lattice edge length;
///   double value(Vertex): the sign of f, 0 once warped (S5, S6);
///   Vec3 pos(Key): the output vertex in space;
///   d3::Point point_of(Key): the lattice point a key names first.
/// The output tetrahedra, positively oriented (S12), and their levels
/// collect in tets_out_ and levels_out_ in order of emission. A stuffer may
/// keep its output vertices as something smaller than keys (`Stored`); it
/// then also supplies Stored store(Key) and Vec3 stored_pos(Stored).
template <class Derived, class Vertex, class Key, class Stored = Key>
class Stencils {
 protected:
  /// S7: fills the lattice tetrahedron t, whose leaf has level `level()`
  /// (asked once, and only when something is emitted).
  template <class Level>
  void fill(const std::array<Vertex, 4>& t, Level&& level) {
    std::array<Vertex, 4> neg{}, zero{}, plus{};
    std::size_t n = 0, z = 0, np = 0;
    for (const Vertex& p : t) {
      const double v = self().value(p);
      if (v < 0)
        neg[n++] = p;
      else if (v > 0)
        plus[np++] = p;
      else
        zero[z++] = p;
    }
    const auto L = [this](const Vertex& p) { return self().lattice_key(p); };
    const auto C = [this](const Vertex& x, const Vertex& y) { return self().cut_key(x, y); };
    if (np == 0) {
      // All four zero: nothing (the surface passes through every vertex, so
      // the tetrahedron is a sliver along it; S7).
      if (n != 0) emit({L(t[0]), L(t[1]), L(t[2]), L(t[3])}, level());
      return;
    }
    if (n == 0) return;
    const int l = level();
    if (n == 1 && z == 0) {
      const Vertex& a = neg[0];
      emit({L(a), C(a, plus[0]), C(a, plus[1]), C(a, plus[2])}, l);
    } else if (n == 1 && z == 1) {
      const Vertex& a = neg[0];
      emit({L(a), L(zero[0]), C(a, plus[0]), C(a, plus[1])}, l);
    } else if (n == 1 && z == 2) {
      const Vertex& a = neg[0];
      emit({L(a), L(zero[0]), L(zero[1]), C(a, plus[0])}, l);
    } else if (n == 2 && z == 1) {
      const Vertex &a = neg[0], &b = neg[1], &p = plus[0];
      pyramid(L(zero[0]), {L(a), L(b), C(b, p), C(a, p)}, face_diagonal(a, b, p), l);
    } else if (n == 3) {
      // A = (a, b, c), B = (c_ap, c_bp, c_cp); Qi lies in the face (Ai, Ai+1, p).
      const Vertex& p = plus[0];
      std::array<Key, 3> A{}, B{};
      std::array<bool, 3> d{};
      for (std::size_t i = 0; i < 3; ++i) A[i] = L(neg[i]), B[i] = C(neg[i], p);
      for (std::size_t i = 0; i < 3; ++i)
        d[i] = diag_bit(face_diagonal(neg[i], neg[(i + 1) % 3], p), A[i], B[(i + 1) % 3]);
      prism(A, B, d, l);
    } else {
      // 2 0 2: A = (a, c_ap, c_aq), B = (b, c_bp, c_bq); Q0 in face (a, b, p),
      // Q2 in face (a, b, q), Q1 = (c_ap, c_aq, c_bq, c_bp) inside, free.
      const Vertex &a = neg[0], &b = neg[1], &p = plus[0], &q = plus[1];
      const std::array<Key, 3> A{L(a), C(a, p), C(a, q)}, B{L(b), C(b, p), C(b, q)};
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
          prism(A, B, d, l);
          const double m = min_angle(before);
          tets_out_.resize(before);
          levels_out_.resize(before);
          if (m > best) best = m, best_d1 = d1;
        }
        d[1] = best_d1;
      } else {
        d[1] = !d[0];
      }
      prism(A, B, d, l);
    }
  }

  std::vector<std::array<Stored, 4>> tets_out_;
  std::vector<int> levels_out_;

  /// Whether a flat output tetrahedron is written rather than refused
  /// (S35.7's placed cut points); a stuffer says so by its own.
  bool flat_allowed() const { return false; }

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }

  /// The angle at p between the directions to x and y.
  static double angle(const Vec3& p, const Vec3& x, const Vec3& y) {
    const Vec3 u{x[0] - p[0], x[1] - p[1], x[2] - p[2]}, v{y[0] - p[0], y[1] - p[1], y[2] - p[2]};
    const double c = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) /
                     std::sqrt((u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    return std::acos(std::clamp(c, -1.0, 1.0));
  }

  // S8: the diagonal of the face quadrilateral (a, b, c_bt, c_at) as a pair of keys.
  std::pair<Key, Key> face_diagonal(const Vertex& a, const Vertex& b, const Vertex& t) const {
    const Derived& s = self();
    const Key ka = s.lattice_key(a), kb = s.lattice_key(b), cat = s.cut_key(a, t), cbt = s.cut_key(b, t);
    const std::int64_t la = s.length2(a, t), lb = s.length2(b, t);
    if (la > lb) return {cat, kb};
    if (lb > la) return {cbt, ka};
    // Equal: the Delaunay diagonal of the planar quadrilateral (a, b, c_bt,
    // c_at), computed from the ends in position order so that both
    // tetrahedra at the face compute the same; a tie by the smallest key.
    if (b < a) return face_diagonal(b, a, t);
    const Vec3 pa = s.pos(ka), pb = s.pos(kb), pbt = s.pos(cbt), pat = s.pos(cat);
    const double at_b = angle(pb, pa, pbt), at_cat = angle(pat, pbt, pa);
    const double at_a = angle(pa, pat, pb), at_cbt = angle(pbt, pb, pat);
    if (at_b + at_cat < at_a + at_cbt) return {ka, cbt};
    if (at_b + at_cat > at_a + at_cbt) return {kb, cat};
    const Key m = std::min({ka, kb, cat, cbt});
    if (m == ka || m == cbt) return {ka, cbt};
    return {kb, cat};
  }

  void emit(const std::array<Key, 4>& t, int level) {
    const Derived& s = self();
    std::array<Key, 4> v = t;
    const int o = orientation(s.pos(v[0]), s.pos(v[1]), s.pos(v[2]), s.pos(v[3]));
    // S35.7: with cut points placed off their edges a flat one is written
    // as it is, for its guard to refuse.
    if (o == 0 && !s.flat_allowed())
      throw std::logic_error("stuff: a flat output tetrahedron near " + d3::to_string(s.point_of(v[0])));
    if (o < 0) std::swap(v[2], v[3]);
    if constexpr (std::is_same_v<Stored, Key>)
      tets_out_.push_back(v);
    else
      tets_out_.push_back({s.store(v[0]), s.store(v[1]), s.store(v[2]), s.store(v[3])});
    levels_out_.push_back(level);
  }

  /// The pyramid with apex x over the quadrilateral q (cyclic), split by the
  /// diagonal d (two opposite corners of q).
  void pyramid(const Key& x, const std::array<Key, 4>& q, const std::pair<Key, Key>& d, int level) {
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
  void prism(const std::array<Key, 3>& A, const std::array<Key, 3>& B, const std::array<bool, 3>& d, int level) {
    if (d[0] == d[1] && d[1] == d[2]) throw std::logic_error("stuff: cyclic prism diagonals (S9)");
    for (std::size_t i = 0; i < 3; ++i) {
      const std::size_t n = (i + 1) % 3, p = (i + 2) % 3;  // i+1, i-1
      const bool two_at_A = d[i] && !d[p], two_at_B = !d[i] && d[p];
      if (!two_at_A && !two_at_B) continue;
      // Q(i+1) = (A n, A p, B p, B n), its diagonal A n B p (d[n]) or A p B n.
      const std::array<Key, 4> q{A[n], A[p], B[p], B[n]};
      const std::pair<Key, Key> diag = d[n] ? std::make_pair(A[n], B[p]) : std::make_pair(A[p], B[n]);
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
  static bool diag_bit(const std::pair<Key, Key>& diag, const Key& x0, const Key& y1) {
    return (diag.first == x0 && diag.second == y1) || (diag.first == y1 && diag.second == x0);
  }

  /// The smallest dihedral angle of the tetrahedra emitted from `from` on.
  double min_angle(std::size_t from) const {
    const Derived& s = self();
    double m = 180;
    for (std::size_t i = from; i < tets_out_.size(); ++i) {
      const auto& t = tets_out_[i];
      const auto pos = [&s](const Stored& x) {
        if constexpr (std::is_same_v<Stored, Key>)
          return s.pos(x);
        else
          return s.stored_pos(x);
      };
      for (const double a : d3::dihedral_angles(std::array<Vec3, 4>{pos(t[0]), pos(t[1]), pos(t[2]), pos(t[3])}))
        m = std::min(m, a);
    }
    return m;
  }
};

}  // namespace bccmis::stuff::detail
