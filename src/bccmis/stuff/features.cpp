// S29: the sharp features of a triangle mesh (features.h).
#include "bccmis/stuff/features.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

namespace bccmis::stuff {

namespace {

Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& u, const Vec3& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
double dot(const Vec3& u, const Vec3& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
double norm(const Vec3& u) { return std::sqrt(dot(u, u)); }

/// S29's theta: the angle between u and v in degrees, atan2(|u x v|, u . v) 180 / pi.
double angle_between(const Vec3& u, const Vec3& v) {
  return std::atan2(norm(cross(u, v)), dot(u, v)) * 180 / std::numbers::pi;
}

/// A triangle's side of an edge: which triangle, and whether it runs along
/// the edge from its smaller vertex to its larger.
struct Side {
  std::uint32_t triangle;
  bool forward;
};

}  // namespace

double FeatureCurve::length() const {
  double sum = 0;
  for (std::size_t i = 1; i < points.size(); ++i) sum += norm(minus(points[i], points[i - 1]));
  return sum;
}

CurvePoint nearest_on_segment(const Vec3& a, const Vec3& b, const Vec3& x) {
  const Vec3 ab = minus(b, a);
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(minus(x, a), ab) / len2, 0.0, 1.0) : 0.0;
  const Vec3 p = t == 1 ? b : Vec3{a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]};
  return {norm(minus(x, p)), t, p};
}

CurvePoint nearest_on_curve(const FeatureCurve& curve, const Vec3& x) {
  CurvePoint best{HUGE_VAL, 0, curve.points.front()};
  double s = 0;
  for (std::size_t i = 1; i < curve.points.size(); ++i) {
    const double len = norm(minus(curve.points[i], curve.points[i - 1]));
    CurvePoint p = nearest_on_segment(curve.points[i - 1], curve.points[i], x);
    p.s = s + p.s * len;
    if (p.distance < best.distance) best = p;
    s += len;
  }
  return best;
}

Features detect_features(std::span<const std::array<Vec3, 3>> triangles, double angle) {
  Features f;
  f.angle = angle;
  // Weld: vertex ids in coordinate order.
  std::vector<Vec3> V;
  V.reserve(3 * triangles.size());
  for (const auto& t : triangles) V.insert(V.end(), t.begin(), t.end());
  std::sort(V.begin(), V.end());
  V.erase(std::unique(V.begin(), V.end()), V.end());
  const auto id = [&](const Vec3& p) {
    return static_cast<std::uint32_t>(std::lower_bound(V.begin(), V.end(), p) - V.begin());
  };
  std::vector<std::array<std::uint32_t, 3>> T;
  std::vector<Vec3> normal;
  for (const auto& t : triangles) {
    const std::array<std::uint32_t, 3> ids{id(t[0]), id(t[1]), id(t[2])};
    if (ids[0] == ids[1] || ids[1] == ids[2] || ids[2] == ids[0]) continue;
    T.push_back(ids);
    normal.push_back(cross(minus(t[1], t[0]), minus(t[2], t[0])));
  }
  // Each edge with the triangles along it.
  std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, Side>> sides;
  sides.reserve(3 * T.size());
  for (std::uint32_t k = 0; k < T.size(); ++k)
    for (std::size_t i = 0; i < 3; ++i) {
      const std::uint32_t u = T[k][i], w = T[k][(i + 1) % 3];
      sides.push_back({{std::min(u, w), std::max(u, w)}, Side{k, u < w}});
    }
  std::sort(sides.begin(), sides.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  // S29: an edge of exactly two triangles whose normals turn by more than phi.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> E;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j].first == sides[i].first) ++j;
    if (j - i == 2) {
      const Side &s1 = sides[i].second, &s2 = sides[i + 1].second;
      Vec3 n2 = normal[s2.triangle];
      if (s1.forward == s2.forward) n2 = {-n2[0], -n2[1], -n2[2]};  // orientation not consistent
      if (angle_between(normal[s1.triangle], n2) > angle) E.push_back(sides[i].first);
    }
    i = j;
  }
  f.edges = E.size();
  // Each vertex's feature edges.
  std::vector<std::vector<std::uint32_t>> at(V.size());
  for (std::uint32_t e = 0; e < E.size(); ++e) {
    at[E[e].first].push_back(e);
    at[E[e].second].push_back(e);
  }
  const auto other = [&](std::uint32_t e, std::uint32_t v) { return E[e].first == v ? E[e].second : E[e].first; };
  // S29's corners: 1 or >= 3 feature edges, or 2 with a turn sharper than phi.
  std::vector<char> corner(V.size(), 0);
  for (std::uint32_t v = 0; v < V.size(); ++v) {
    const std::size_t n = at[v].size();
    if (n == 1 || n >= 3) corner[v] = 1;
    if (n == 2 && angle_between(minus(V[v], V[other(at[v][0], v)]), minus(V[other(at[v][1], v)], V[v])) > angle)
      corner[v] = 1;
    if (corner[v]) f.corners.push_back(V[v]);
  }
  // S29's curves: maximal chains through vertices that are not corners.
  std::vector<char> used(E.size(), 0);
  // From v along e, through vertices that are not corners: the vertices met
  // (v excluded), stopping at a corner or on coming back to `stop`.
  const auto walk = [&](std::uint32_t v, std::uint32_t e, std::uint32_t stop) {
    std::vector<std::uint32_t> chain;
    for (;;) {
      used[e] = 1;
      v = other(e, v);
      chain.push_back(v);
      if (corner[v] || v == stop) return chain;
      e = at[v][0] == e ? at[v][1] : at[v][0];
    }
  };
  for (std::uint32_t e = 0; e < E.size(); ++e) {
    if (used[e]) continue;
    const auto [a, b] = E[e];
    std::vector<std::uint32_t> chain = walk(a, e, a);  // b ... to a corner, or back to a
    FeatureCurve c;
    if (!corner[a] && chain.back() == a) {  // a loop: from its smallest vertex toward its smaller neighbour
      c.closed = true;
      chain.pop_back();
      chain.insert(chain.begin(), a);
      const auto first = std::min_element(chain.begin(), chain.end());
      std::rotate(chain.begin(), first, chain.end());
      if (chain.back() < chain[1]) std::reverse(chain.begin() + 1, chain.end());
      chain.push_back(chain.front());
    } else {
      std::vector<std::uint32_t> back{a};
      if (!corner[a]) {  // the other way from a, to its corner
        const std::uint32_t e2 = at[a][0] == e ? at[a][1] : at[a][0];
        const auto rest = walk(a, e2, a);
        back.insert(back.begin(), rest.rbegin(), rest.rend());
      }
      back.insert(back.end(), chain.begin(), chain.end());
      chain = std::move(back);
      if (chain.back() < chain.front()) std::reverse(chain.begin(), chain.end());
    }
    for (const std::uint32_t v : chain) c.points.push_back(V[v]);
    f.curves.push_back(std::move(c));
  }
  return f;
}

}  // namespace bccmis::stuff
