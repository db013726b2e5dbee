// The stuffed-mesh layer of the 3D checker (stuffed_mesh.h; spec/invariants.md,
// "3D stuffed-mesh layer").
#include "bccmis/invariants/d3/stuffed_mesh.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <utility>

namespace bccmis::d3 {

namespace {

using P = std::array<double, 3>;
const std::string kSection = "spec/stuffing.md S7, S10-S12";

Violation violation(const std::string& code, const std::string& message) {
  Violation v;
  v.code = code;
  v.message = code + ": " + message;
  v.section = kSection;
  v.layer = 7;
  return v;
}

/// The sign of det[b - a, c - a, d - a]: in long double with a forward error
/// bound (each difference rounds once, each of the six triple products and
/// the sums a few times more: 16 units of the long double's rounding error
/// on the sum of their magnitudes is a safe margin), otherwise exactly in
/// rational arithmetic from the doubles.
int orientation_sign(const P& a, const P& b, const P& c, const P& d) {
  using L = long double;
  L m[3][3];
  for (int k = 0; k < 3; ++k) {
    m[0][k] = L{b[static_cast<std::size_t>(k)]} - L{a[static_cast<std::size_t>(k)]};
    m[1][k] = L{c[static_cast<std::size_t>(k)]} - L{a[static_cast<std::size_t>(k)]};
    m[2][k] = L{d[static_cast<std::size_t>(k)]} - L{a[static_cast<std::size_t>(k)]};
  }
  const L t[6] = {m[0][0] * m[1][1] * m[2][2], -m[0][0] * m[1][2] * m[2][1], -m[0][1] * m[1][0] * m[2][2],
                  m[0][1] * m[1][2] * m[2][0], m[0][2] * m[1][0] * m[2][1],  -m[0][2] * m[1][1] * m[2][0]};
  L det = 0, magnitude = 0;
  for (const L x : t) det += x, magnitude += std::fabs(x);
  const L bound = 16 * std::numeric_limits<L>::epsilon() * magnitude;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  mpq_class e[3][3];
  for (std::size_t k = 0; k < 3; ++k) {
    e[0][k] = mpq_class(b[k]) - mpq_class(a[k]);
    e[1][k] = mpq_class(c[k]) - mpq_class(a[k]);
    e[2][k] = mpq_class(d[k]) - mpq_class(a[k]);
  }
  const mpq_class exact = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                          e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                          e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  return sgn(exact);
}

/// The dihedral angle (degrees) at edge pq between the faces pqr and pqs.
double dihedral(const P& p, const P& q, const P& r, const P& s) {
  using L = long double;
  const auto sub = [](const P& x, const P& y) {
    return std::array<L, 3>{L{x[0]} - y[0], L{x[1]} - y[1], L{x[2]} - y[2]};
  };
  const auto cross = [](const std::array<L, 3>& u, const std::array<L, 3>& v) {
    return std::array<L, 3>{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  };
  const auto dot = [](const std::array<L, 3>& u, const std::array<L, 3>& v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  };
  const auto e = sub(q, p);
  const auto n1 = cross(e, sub(r, p)), n2 = cross(e, sub(s, p));
  const L c = dot(n1, n2) / std::sqrt(dot(n1, n1) * dot(n2, n2));
  return static_cast<double>(std::acos(std::clamp(c, L{-1}, L{1})) * 180 / std::numbers::pi_v<L>);
}

std::string triple(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  return "(" + std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c) + ")";
}

}  // namespace

std::optional<Violation> check_stuffed_mesh(std::span<const P> vertices,
                                            std::span<const std::array<std::uint32_t, 4>> tets,
                                            const StuffedMeshClaims& claims) {
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const auto& t = tets[i];
    for (const std::uint32_t v : t)
      if (v >= vertices.size())
        return violation("stuffed-orientation", "tetrahedron " + std::to_string(i) + " names vertex " +
                                                    std::to_string(v) + " of " + std::to_string(vertices.size()));
    if (orientation_sign(vertices[t[0]], vertices[t[1]], vertices[t[2]], vertices[t[3]]) != 1)
      return violation("stuffed-orientation", "tetrahedron " + std::to_string(i) + " is not positively oriented");
  }
  // Each face of a positively oriented (a, b, c, d), oriented outward.
  std::map<std::array<std::uint32_t, 3>, std::pair<int, std::array<std::uint32_t, 3>>> faces;
  for (const auto& t : tets)
    for (const std::array<std::uint32_t, 3> f : {std::array{t[0], t[2], t[1]}, std::array{t[0], t[1], t[3]},
                                                 std::array{t[0], t[3], t[2]}, std::array{t[1], t[2], t[3]}}) {
      std::array<std::uint32_t, 3> key = f;
      std::sort(key.begin(), key.end());
      auto& [count, outward] = faces[key];
      if (++count > 2)
        return violation("stuffed-face-count",
                         "the triangle " + triple(key[0], key[1], key[2]) + " is in more than two tetrahedra");
      outward = f;
    }
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& [key, entry] : faces) {
    if (entry.first != 1) continue;
    const auto& f = entry.second;
    for (std::size_t i = 0; i < 3; ++i) {
      ++edges[{f[i], f[(i + 1) % 3]}];
      if (!(std::abs(claims.distance(vertices[f[i]])) <= claims.tolerance))
        return violation("stuffed-off-surface", "boundary vertex " + std::to_string(f[i]) + " is off the surface");
    }
  }
  // Closed: thin parts of a shape at a coarse level may meet along an edge,
  // which then has two boundary triangles each way (S11).
  for (const auto& [e, n] : edges)
    if (const auto back = edges.find({e.second, e.first}); back == edges.end() || back->second != n)
      return violation("stuffed-open", "the boundary is not closed at the edge (" + std::to_string(e.first) + ", " +
                                           std::to_string(e.second) + ")");
  if (claims.dihedral) {
    const auto [lo, hi] = *claims.dihedral;
    for (std::size_t i = 0; i < tets.size(); ++i) {
      const auto& t = tets[i];
      const P &a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]], &d = vertices[t[3]];
      for (const double angle : {dihedral(a, b, c, d), dihedral(a, c, b, d), dihedral(a, d, b, c), dihedral(b, c, a, d),
                                 dihedral(b, d, a, c), dihedral(c, d, a, b)})
        if (!(angle >= lo && angle <= hi))
          return violation("stuffed-dihedral", "tetrahedron " + std::to_string(i) + " has a dihedral angle of " +
                                                   std::to_string(angle) + " degrees, outside [" + std::to_string(lo) +
                                                   ", " + std::to_string(hi) + "]");
    }
  }
  return std::nullopt;
}

}  // namespace bccmis::d3
