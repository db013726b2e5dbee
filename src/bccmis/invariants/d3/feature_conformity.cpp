// The feature layer of the 3D checker (feature_conformity.h; spec/stuffing.md S32).
#include "bccmis/invariants/d3/feature_conformity.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <utility>

namespace bccmis::d3 {

namespace {

using P = std::array<double, 3>;
using L = long double;

Violation violation(const std::string& code, const std::string& message) {
  Violation v;
  v.code = code;
  v.message = code + ": " + message;
  v.section = "spec/stuffing.md S32";
  v.layer = 8;
  return v;
}

std::string point(const P& p) {
  std::ostringstream out;
  out.precision(17);
  out << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return out.str();
}

L length(const P& a, const P& b) {
  const L x = L{a[0]} - b[0], y = L{a[1]} - b[1], z = L{a[2]} - b[2];
  return std::sqrt(x * x + y * y + z * z);
}

/// The distance from x to the segment [a, b], and the fraction along it of
/// the nearest point.
std::pair<L, L> to_segment(const P& x, const P& a, const P& b) {
  L ab[3], ax[3], dd = 0, dot = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    ab[k] = L{b[k]} - a[k];
    ax[k] = L{x[k]} - a[k];
    dd += ab[k] * ab[k];
    dot += ab[k] * ax[k];
  }
  const L t = dd > 0 ? std::clamp(dot / dd, L{0}, L{1}) : L{0};
  L d2 = 0;
  for (std::size_t k = 0; k < 3; ++k) d2 += (ax[k] - t * ab[k]) * (ax[k] - t * ab[k]);
  return {std::sqrt(d2), t};
}

/// A curve with the arc length at each of its vertices.
struct Curve {
  const std::vector<P>& points;
  std::vector<L> s;
  explicit Curve(const std::vector<P>& p) : points(p), s(p.size(), 0) {
    for (std::size_t i = 1; i < p.size(); ++i) s[i] = s[i - 1] + length(p[i - 1], p[i]);
  }
  /// The distance from x to the curve and the arc length of its nearest point.
  std::pair<L, L> locate(const P& x) const {
    std::pair<L, L> best{HUGE_VALL, 0};
    for (std::size_t i = 1; i < points.size(); ++i) {
      const auto [d, t] = to_segment(x, points[i - 1], points[i]);
      if (d < best.first) best = {d, s[i - 1] + t * (s[i] - s[i - 1])};
    }
    return best;
  }
};

}  // namespace

std::optional<Violation> check_feature_conformity(std::span<const P> vertices,
                                                  std::span<const std::array<std::uint32_t, 4>> tets,
                                                  const FeatureClaims& claims) {
  for (std::size_t c = 0; c < claims.corners.size(); ++c) {
    bool found = false;
    for (const P& v : vertices) found = found || length(v, claims.corners[c]) <= claims.tolerance;
    if (!found)
      return violation("feature-corner",
                       "no mesh vertex at corner " + std::to_string(c) + " " + point(claims.corners[c]));
  }
  // The boundary: the triangles of exactly one tetrahedron, and their edges.
  std::map<std::array<std::uint32_t, 3>, int> faces;
  for (const auto& t : tets)
    for (const auto& f : {std::array{t[0], t[1], t[2]}, std::array{t[0], t[1], t[3]}, std::array{t[0], t[2], t[3]},
                          std::array{t[1], t[2], t[3]}}) {
      auto key = f;
      std::sort(key.begin(), key.end());
      ++faces[key];
    }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& [f, n] : faces)
    if (n == 1) edges.insert(edges.end(), {{f[0], f[1]}, {f[1], f[2]}, {f[0], f[2]}});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (std::size_t c = 0; c < claims.curves.size(); ++c) {
    const Curve curve(claims.curves[c]);
    P lo = curve.points.front(), hi = lo;
    for (const P& p : curve.points)
      for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    const auto near_box = [&](const P& x) {
      for (std::size_t k = 0; k < 3; ++k)
        if (x[k] < lo[k] - claims.tolerance || x[k] > hi[k] + claims.tolerance) return false;
      return true;
    };
    std::vector<std::pair<L, L>> covered;
    for (const auto& [u, w] : edges) {
      if (u >= vertices.size() || w >= vertices.size() || !near_box(vertices[u]) || !near_box(vertices[w])) continue;
      const auto [du, su] = curve.locate(vertices[u]);
      const auto [dw, sw] = curve.locate(vertices[w]);
      if (!(du <= claims.tolerance && dw <= claims.tolerance) || su == sw) continue;
      const L a = std::min(su, sw), b = std::max(su, sw);
      bool chord = true;
      for (std::size_t i = 0; i < curve.points.size(); ++i)
        if (curve.s[i] > a && curve.s[i] < b)
          chord = chord && to_segment(curve.points[i], vertices[u], vertices[w]).first <= claims.chord;
      if (chord) covered.emplace_back(a, b);
    }
    std::sort(covered.begin(), covered.end());
    L reach = 0;
    for (const auto& [a, b] : covered) {
      if (a > reach + claims.tolerance) break;
      reach = std::max(reach, b);
    }
    if (reach < curve.s.back() - claims.tolerance)
      return violation("feature-uncovered", "curve " + std::to_string(c) + " is not covered by boundary edges from " +
                                                "arc length " + std::to_string(static_cast<double>(reach)) + " of " +
                                                std::to_string(static_cast<double>(curve.s.back())));
  }
  return std::nullopt;
}

}  // namespace bccmis::d3
