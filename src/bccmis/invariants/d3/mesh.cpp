// 3D layer 5, the tetrahedral mesh (spec/invariants.md, "3D layer 5"): a list
// of tetrahedra must tile the box, be positively oriented with dihedral
// angles in [45°, 120°], and have exactly the graph's node-center edges.
//
// In this order (per tetrahedron in list order first, then global):
//   mesh-vertex        every vertex is a node, a center or a hull vertex (the
//                      center of a leaf's face in the domain boundary)
//   tet-orientation    det[b - a, c - a, d - a] > 0, exactly (GMP)
//   dihedral-angle     every dihedral angle in [45°, 120°] ± 1e-9° (long double)
//   mesh-volume        the six-fold volumes sum to 6*W*H*D*S^3, exactly
//   face-sides         no two tets on the same side of a shared triangle
//   face-count         a triangle in the domain boundary is in 1 tet, any other in 2
//   mesh-extra-edge    every tet edge {c, n}, c in C, n in N, is a graph edge
//   mesh-missing-edge  every graph edge is a tet edge
// Coordinates up to 2^63 in magnitude make the orientation determinant up to
// about 2^195, so it is computed with mpz_class; below 2^40 (every box of
// extent below 2^40) in 128-bit integers, exactly, without GMP.
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "bccmis/invariants/d3/detail/lattice_geometry.h"

namespace bccmis::d3 {

namespace {

using inv::coord;
using inv::pos;

constexpr int layer = 5;
const std::string kMeshSection = "spec/invariants.md, 3D layer 5";

mpz_class big(std::int64_t v) { return mpz_class(static_cast<long>(v)); }

__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 UInt128;

/// det[b - a, c - a, d - a] in 128-bit integers when every coordinate is
/// below 2^40 in magnitude (differences below 2^41, each product of three
/// below 2^123, the sum of six below 2^126): exact, and without GMP's
/// allocations, for every box with extents below 2^40. Empty otherwise.
std::optional<Int128> orient_small(const Point& a, const Point& b, const Point& c, const Point& d) {
  constexpr std::int64_t kLimit = std::int64_t{1} << 40;
  std::array<std::array<Int128, 3>, 3> m{};
  const std::array<const Point*, 3> rows{&b, &c, &d};
  for (std::size_t i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      const std::int64_t p = coord(*rows[i], k), q = coord(a, k);
      if (p >= kLimit || p <= -kLimit || q >= kLimit || q <= -kLimit) return std::nullopt;  // p - q below 2^41
      m[i][static_cast<std::size_t>(k)] = Int128{p} - Int128{q};
    }
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/// det[b - a, c - a, d - a], exactly: six times the signed volume.
mpz_class orient_big(const Point& a, const Point& b, const Point& c, const Point& d) {
  std::array<std::array<mpz_class, 3>, 3> m;
  const std::array<const Point*, 3> rows{&b, &c, &d};
  for (std::size_t i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) m[i][static_cast<std::size_t>(k)] = big(coord(*rows[i], k)) - big(coord(a, k));
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/// The sign of det[b - a, c - a, d - a], exactly.
int orient_sign(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (const std::optional<Int128> v = orient_small(a, b, c, d)) return (*v > 0) - (*v < 0);
  return sgn(orient_big(a, b, c, d));
}

/// det[b - a, c - a, d - a] as an mpz_class, by the fast path when it applies.
mpz_class orient(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (const std::optional<Int128> v = orient_small(a, b, c, d)) {
    // |v| < 2^126: two 64-bit halves.
    const bool negative = *v < 0;
    const auto u = static_cast<UInt128>(negative ? -*v : *v);
    mpz_class r = static_cast<unsigned long>(static_cast<std::uint64_t>(u >> 64));
    r <<= 64;
    r += static_cast<unsigned long>(static_cast<std::uint64_t>(u));
    return negative ? mpz_class(-r) : r;
  }
  return orient_big(a, b, c, d);
}

std::string tet_text(std::size_t i, const Tet& t) {
  return "tet #" + std::to_string(i) + " (" + pos(t[0]) + ", " + pos(t[1]) + ", " + pos(t[2]) + ", " + pos(t[3]) + ")";
}

using Vec = std::array<long double, 3>;

Vec diff(const Point& p, const Point& q) {  // p - q, exact for int64 input in long double's 64-bit mantissa
  return {static_cast<long double>(p.x) - static_cast<long double>(q.x),
          static_cast<long double>(p.y) - static_cast<long double>(q.y),
          static_cast<long double>(p.z) - static_cast<long double>(q.z)};
}
long double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// The interior dihedral angle, in degrees, at the edge (p, q) between the
/// faces through r and through s: the angle between r and s projected onto
/// the plane perpendicular to the edge.
long double dihedral(const Point& p, const Point& q, const Point& r, const Point& s) {
  const Vec e = diff(q, p);
  const long double ee = dot(e, e);
  Vec u = diff(r, p), v = diff(s, p);
  const long double fu = dot(u, e) / ee, fv = dot(v, e) / ee;
  for (std::size_t k = 0; k < 3; ++k) {
    u[k] -= fu * e[k];
    v[k] -= fv * e[k];
  }
  long double c = dot(u, v) / std::sqrt(dot(u, u) * dot(v, v));
  c = std::clamp(c, -1.0L, 1.0L);
  return std::acos(c) * 180.0L / std::numbers::pi_v<long double>;
}

}  // namespace

std::optional<Violation> check_mesh(const Graph& g, std::span<const Tet> tets) {
  if (auto v = inv::check_lattice_size(g.size)) return v;
  const inv::Box box(g.size);
  auto fail = [](std::string code, std::vector<Point> where, const std::string& text, const std::string& section) {
    return inv::violation(layer, std::move(code), std::move(where), text, section);
  };

  // mesh-vertex: the hull vertices are the centers of leaf faces lying in the
  // domain boundary.
  std::set<Point> hull;
  for (const auto& [c, l] : g.level) {
    const std::int64_t h = box.half(l);
    if (h == 0 || !box.contains(c)) continue;
    for (int a = 0; a < 3; ++a)
      for (const std::int64_t d : {-h, h}) {
        const std::int64_t v = coord(c, a) + d;
        if (v != 0 && v != box.extent[static_cast<std::size_t>(a)]) continue;
        hull.insert({c.x + (a == 0 ? d : 0), c.y + (a == 1 ? d : 0), c.z + (a == 2 ? d : 0)});
      }
  }
  for (std::size_t i = 0; i < tets.size(); ++i)
    for (const Point& p : tets[i])
      if (!g.N.count(p) && !g.C.count(p) && !hull.count(p))
        return fail("mesh-vertex", {p},
                    tet_text(i, tets[i]) + " has the vertex " + pos(p) +
                        ", which is neither a node, a center nor the center of a leaf's face in the domain boundary",
                    "§1");

  // tet-orientation; the six-fold volumes are summed as they come, in
  // 128 bits while every one is small (a sum of positive values below 2^126
  // each stays exact as long as it fits; it moves to GMP before it could not).
  mpz_class sum = 0;
  Int128 small_sum = 0;
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const Tet& t = tets[i];
    const std::optional<Int128> small = orient_small(t[0], t[1], t[2], t[3]);
    if (small && *small > 0 && small_sum < (Int128{1} << 126)) {
      small_sum += *small;
      continue;
    }
    const mpz_class v = orient(t[0], t[1], t[2], t[3]);
    if (sgn(v) <= 0)
      return fail("tet-orientation", {t[0], t[1], t[2], t[3]},
                  tet_text(i, t) + " has six-fold signed volume " + v.get_str() +
                      "; every tetrahedron must be positively oriented",
                  kMeshSection);
    sum += v;
  }

  // dihedral-angle
  constexpr long double kTolerance = 1e-9L, kMin = 45.0L, kMax = 120.0L;
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const Tet& t = tets[i];
    for (std::size_t a = 0; a < 4; ++a)
      for (std::size_t b = a + 1; b < 4; ++b) {
        std::size_t r = 0;
        while (r == a || r == b) ++r;
        std::size_t s = r + 1;
        while (s == a || s == b) ++s;
        const long double angle = dihedral(t[a], t[b], t[r], t[s]);
        if (angle < kMin - kTolerance || angle > kMax + kTolerance)
          return fail("dihedral-angle", {t[a], t[b]},
                      tet_text(i, t) + " has a dihedral angle of " + std::to_string(static_cast<double>(angle)) +
                          " degrees at the edge " + pos(t[a]) + " - " + pos(t[b]) + ", outside [45, 120]",
                      kMeshSection);
      }
  }

  // mesh-volume
  {
    if (small_sum != 0) {
      const auto u = static_cast<UInt128>(small_sum);
      mpz_class high = static_cast<unsigned long>(static_cast<std::uint64_t>(u >> 64));
      high <<= 64;
      sum += high + static_cast<unsigned long>(static_cast<std::uint64_t>(u));
    }
    mpz_class want = 6;
    for (const std::int64_t e : box.extent) want *= big(e);
    if (sum != want)
      return fail("mesh-volume", {},
                  "the " + std::to_string(tets.size()) + " tetrahedra have six-fold volumes summing to " +
                      sum.get_str() + ", not 6*W*H*D*S^3 = " + want.get_str(),
                  "§1");
  }

  // The triangles: sorted vertex triple -> (tet, side of the fourth vertex).
  using Triangle = std::array<Point, 3>;
  std::map<Triangle, std::vector<std::pair<std::size_t, int>>> faces;
  for (std::size_t i = 0; i < tets.size(); ++i)
    for (std::size_t skip = 0; skip < 4; ++skip) {
      Triangle tri;
      std::size_t k = 0;
      for (std::size_t j = 0; j < 4; ++j)
        if (j != skip) tri[k++] = tets[i][j];
      std::sort(tri.begin(), tri.end());
      faces[tri].push_back({i, orient_sign(tri[0], tri[1], tri[2], tets[i][skip])});
    }
  auto tri_text = [](const Triangle& t) { return "the triangle " + pos(t[0]) + ", " + pos(t[1]) + ", " + pos(t[2]); };

  // face-sides
  for (const auto& [tri, users] : faces)
    for (std::size_t a = 0; a < users.size(); ++a)
      for (std::size_t b = a + 1; b < users.size(); ++b)
        if (users[a].second == users[b].second)
          return fail("face-sides", {tri[0], tri[1], tri[2]},
                      "tets #" + std::to_string(users[a].first) + " and #" + std::to_string(users[b].first) +
                          " both lie on the same side of " + tri_text(tri) + " (they overlap)",
                      kMeshSection);

  // face-count
  for (const auto& [tri, users] : faces) {
    bool in_boundary = false;
    for (int a = 0; a < 3; ++a)
      for (const std::int64_t v : {std::int64_t{0}, box.extent[static_cast<std::size_t>(a)]})
        in_boundary = in_boundary || (coord(tri[0], a) == v && coord(tri[1], a) == v && coord(tri[2], a) == v);
    const std::size_t want = in_boundary ? 1 : 2;
    if (users.size() != want)
      return fail("face-count", {tri[0], tri[1], tri[2]},
                  tri_text(tri) + " is a face of " + std::to_string(users.size()) + " tetrahedra (first #" +
                      std::to_string(users.front().first) + "); " +
                      (in_boundary ? "in the domain boundary it must be a face of exactly 1"
                                   : "inside the box it must be a face of exactly 2"),
                  kMeshSection);
  }

  // mesh-extra-edge / mesh-missing-edge: the node-center edges of the mesh.
  std::set<std::pair<Point, Point>> edges;  // (center, node)
  for (std::size_t i = 0; i < tets.size(); ++i)
    for (const Point& c : tets[i])
      for (const Point& n : tets[i]) {
        if (!g.C.count(c) || !g.N.count(n)) continue;
        if (!g.nbr(c).count(n))
          return fail("mesh-extra-edge", {c, n},
                      tet_text(i, tets[i]) + " has the edge from center " + pos(c) + " to node " + pos(n) +
                          ", which is not an edge of the graph",
                      "§1");
        edges.insert({c, n});
      }
  for (const Point& c : g.C)
    for (const Point& n : g.nbr(c))
      if (!edges.count({c, n}))
        return fail("mesh-missing-edge", {c, n},
                    "the graph edge from center " + pos(c) + " to node " + pos(n) + " is an edge of no tetrahedron",
                    "§1");
  return std::nullopt;
}

}  // namespace bccmis::d3
