// The generalized winding number of a triangle soup (spec/stuffing.md S17-S19):
// the exact sum (S17), the hierarchy with its certified far field (S18), the
// side of a point off and on the triangles (S18, S19).
#include "bccmis/soup/winding_number.h"

#include <gmpxx.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <stdexcept>
#include <utility>

namespace bccmis::soup {

namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;  // unit roundoff 2^-53
constexpr double kPi = std::numbers::pi;
constexpr double k4Pi = 4 * std::numbers::pi;
constexpr std::uint32_t kLeafSize = 8;
constexpr int kMaxDepth = 60;
constexpr double kSideBeta = 3.5;  // side()'s first pass (S18), by measurement (bench_winding_number)

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

using Points = std::array<Vec3, 3>;

// spec/stuffing.md S17: one triangle's w at q by Van Oosterom and Strackee,
// with a bound on its rounding error.
WindingNumber::Estimate solid_angle(const Points& t, const Vec3& q) {
  const Vec3 a = sub(t[0], q), b = sub(t[1], q), c = sub(t[2], q);
  const double la = norm(a), lb = norm(b), lc = norm(c);
  const double det = dot(a, cross(b, c));
  const double den = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
  const double half = std::atan2(det, den);
  // S18's rounding allowance: forward bounds on det and den (the rounded
  // differences a, b, c included), then the angle of the vector (den, det)
  // moves by at most asin(delta / |v|) <= (pi / 2) delta / |v|.
  const double permanent = std::abs(a[0]) * (std::abs(b[1] * c[2]) + std::abs(b[2] * c[1])) +
                           std::abs(a[1]) * (std::abs(b[2] * c[0]) + std::abs(b[0] * c[2])) +
                           std::abs(a[2]) * (std::abs(b[0] * c[1]) + std::abs(b[1] * c[0]));
  const double delta = 16 * kU * permanent + 64 * kU * (la * lb * lc);
  // |v| by sqrt(det^2 + den^2) (relative error under 3u) unless the squares
  // could overflow or lose precision to underflow; then hypot.
  const double size2 = det * det + den * den;
  const double size = (size2 < 0x1p-960 || size2 > 0x1p960 ? std::hypot(det, den) : std::sqrt(size2)) * (1 - 4 * kU);
  double half_error = kPi;
  if (delta < size) half_error = std::min(kPi, (kPi / 2) * (delta / size) * (1 + 8 * kU));
  half_error += 4 * kU * kPi;  // atan2's own rounding
  return {half / (2 * kPi), half_error / (2 * kPi)};
}

// Exact predicates (spec/stuffing.md S19): a floating-point filter with
// Shewchuk's bounds, then GMP rationals from the doubles.
mpq_class q_of(double x) { return mpq_class(x); }

// The sign of det[a - d, b - d, c - d] (zero iff the four points are coplanar).
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
  const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
  const double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
  const double det = adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy) + cdz * (adx * bdy - bdx * ady);
  const double permanent = (std::abs(bdx * cdy) + std::abs(cdx * bdy)) * std::abs(adz) +
                           (std::abs(cdx * ady) + std::abs(adx * cdy)) * std::abs(bdz) +
                           (std::abs(adx * bdy) + std::abs(bdx * ady)) * std::abs(cdz);
  constexpr double bound = (7.0 + 56.0 * kU) * kU;  // o3derrboundA
  if (det > bound * permanent) return 1;
  if (-det > bound * permanent) return -1;
  const mpq_class ex = q_of(a[0]) - q_of(d[0]), fx = q_of(b[0]) - q_of(d[0]), gx = q_of(c[0]) - q_of(d[0]);
  const mpq_class ey = q_of(a[1]) - q_of(d[1]), fy = q_of(b[1]) - q_of(d[1]), gy = q_of(c[1]) - q_of(d[1]);
  const mpq_class ez = q_of(a[2]) - q_of(d[2]), fz = q_of(b[2]) - q_of(d[2]), gz = q_of(c[2]) - q_of(d[2]);
  return sgn(mpq_class(ez * (fx * gy - gx * fy) + fz * (gx * ey - ex * gy) + gz * (ex * fy - fx * ey)));
}

// The sign of the orientation of (a, b, c) projected along axis k (the
// coordinates k + 1, k + 2 mod 3): positive when counter-clockwise.
int orient2d(const Vec3& a, const Vec3& b, const Vec3& c, int k) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const double l = (b[i] - a[i]) * (c[j] - a[j]), r = (b[j] - a[j]) * (c[i] - a[i]);
  const double det = l - r;
  constexpr double bound = (3.0 + 16.0 * kU) * kU;  // ccwerrboundA
  const double permanent = std::abs(l) + std::abs(r);
  if (det > bound * permanent) return 1;
  if (-det > bound * permanent) return -1;
  const mpq_class e =
      (q_of(b[i]) - q_of(a[i])) * (q_of(c[j]) - q_of(a[j])) - (q_of(b[j]) - q_of(a[j])) * (q_of(c[i]) - q_of(a[i]));
  return sgn(e);
}

struct Node {
  Vec3 lo{}, hi{};                   // the box of the vertices (exact)
  Vec3 c{};                          // the expansion centre, the box's centre
  double r = 0;                      // every vertex within r of c (rounded up)
  double cnorm = 0;                  // |c|
  Vec3 n0{};                         // a unit vector near the triangles' normals (N / |N|)
  double slab = 0;                   // >= |(x - c) . n0| over the triangles
  double delta = 2;                  // >= |n_i - n0| over the triangles' unit normals
  double i1 = 0;                     // sqrt(area i2) >= the sum of the integrals of |x - c|
  double area = 0;                   // sum of the triangles' areas (an upper bound)
  double area_abs = 0;               // sum of |b - a| |c - a| / 2 (for the rounding allowance)
  double mabs = 0;                   // sum of area_i |p_i - c| >= |M| (p_i the centroids)
  double i2 = 0;                     // >= the sum of the integrals of |x - c|^2 over the triangles (<= area r^2)
  Vec3 n{};                          // N = sum of area_i n_i (the dipole)
  std::array<double, 9> m{};         // M = sum of area_i n_i (p_i - c)^T, row-major
  std::uint32_t begin = 0, end = 0;  // the triangles, positions in tree order
  std::uint32_t right = 0;           // the second child (the first is the next node); 0 for a leaf
};

// Where q lies on a triangle that contains it (S19).
struct Hit {
  std::uint32_t pos = 0;  // position in tree order
  int axis = 0;           // a projection axis along which the triangle is not degenerate
  int loc = 0;            // 0 relative interior, 1 on the edge (at, at + 1), 2 the vertex at
  int at = 0;
};

}  // namespace

struct WindingNumber::Impl {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
  std::vector<Points> points;      // the triangles' corners, in tree order
  std::vector<std::uint32_t> ids;  // the input index of each, in tree order
  std::vector<char> degenerate;    // exactly collinear corners (S17: w = 0), in tree order
  std::vector<Node> nodes;
  mutable std::atomic<std::uint64_t> full_sums{0};

  std::uint32_t build(std::vector<std::uint32_t>& order, const std::vector<Vec3>& centroids, std::uint32_t b,
                      std::uint32_t e, int depth);
  void finish(Node& node) const;
  template <class Add>
  void each_solid_angle(std::uint32_t begin, std::uint32_t end, const Vec3& q, std::span<const std::uint32_t> excluded,
                        Add add) const;
  template <class Far, class Add>
  void walk(std::uint32_t root, const Vec3& q, double qnorm, double beta, std::span<const std::uint32_t> excluded,
            Far far, Add add) const;
  Estimate run(const Vec3& q, double beta, std::span<const std::uint32_t> excluded) const;
  Estimate exact(const Vec3& q, std::span<const std::uint32_t> excluded) const;
  bool at_least(const Vec3& q, std::span<const std::uint32_t> excluded, double threshold) const;
  std::vector<Hit> on_triangles(const Vec3& q) const;
  int side_on(const Vec3& q, const std::vector<Hit>& hits) const;
};

// spec/stuffing.md S18: the hierarchy. Median split of the centroids along
// the longest axis of their box, leaves of at most 8 triangles, the nodes
// in one array in pre-order.
std::uint32_t WindingNumber::Impl::build(std::vector<std::uint32_t>& order, const std::vector<Vec3>& centroids,
                                         std::uint32_t b, std::uint32_t e, int depth) {
  if (depth > kMaxDepth) throw std::logic_error("soup::WindingNumber: hierarchy too deep");
  const auto index = static_cast<std::uint32_t>(nodes.size());
  nodes.emplace_back();
  nodes[index].begin = b;
  nodes[index].end = e;
  if (e - b <= kLeafSize) return index;  // finished once the points are in tree order
  Vec3 lo = centroids[order[b]], hi = lo;
  for (std::uint32_t i = b; i < e; ++i)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], centroids[order[i]][k]);
      hi[k] = std::max(hi[k], centroids[order[i]][k]);
    }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
  const std::uint32_t mid = b + (e - b) / 2;
  std::nth_element(order.begin() + b, order.begin() + mid, order.begin() + e,
                   [&](std::uint32_t x, std::uint32_t y) { return centroids[x][axis] < centroids[y][axis]; });
  build(order, centroids, b, mid, depth + 1);
  const std::uint32_t right = build(order, centroids, mid, e, depth + 1);
  nodes[index].right = right;
  return index;
}

// The node's box, centre, radius and moments, from its triangles (leaves)
// or its children; the constructor calls it bottom-up once the points are
// in tree order.
void WindingNumber::Impl::finish(Node& node) const {
  node.lo = points[node.begin][0];
  node.hi = node.lo;
  for (std::uint32_t i = node.begin; i < node.end; ++i)
    for (const Vec3& v : points[i])
      for (int k = 0; k < 3; ++k) {
        node.lo[k] = std::min(node.lo[k], v[k]);
        node.hi[k] = std::max(node.hi[k], v[k]);
      }
  for (int k = 0; k < 3; ++k) node.c[k] = node.lo[k] + (node.hi[k] - node.lo[k]) / 2;
  double r = 0;
  for (std::uint32_t i = node.begin; i < node.end; ++i)
    for (const Vec3& v : points[i]) r = std::max(r, norm(sub(v, node.c)));
  node.r = r * (1 + 8 * kU);
  node.cnorm = norm(node.c);
  node.n = {};
  node.m = {};
  node.area = node.area_abs = node.mabs = node.i2 = 0;
  if (node.right == 0) {
    for (std::uint32_t i = node.begin; i < node.end; ++i) {
      const Points& t = points[i];
      const Vec3 e1 = sub(t[1], t[0]), e2 = sub(t[2], t[0]);
      const Vec3 cr = cross(e1, e2);
      const Vec3 an = {cr[0] / 2, cr[1] / 2, cr[2] / 2};
      const double alpha = norm(e1) * norm(e2) / 2;
      const double area = norm(an) + 16 * kU * alpha;  // >= the true area
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = (t[0][k] + t[1][k] + t[2][k]) / 3;
      const Vec3 pc = sub(p, node.c);
      for (int j = 0; j < 3; ++j) {
        node.n[j] += an[j];
        for (int k = 0; k < 3; ++k) node.m[3 * j + k] += an[j] * pc[k];
      }
      node.area += area;
      node.area_abs += alpha;
      node.mabs += area * norm(pc);
      // The integral of |x - c|^2 over a triangle: area (|p - c|^2 + sum |v - p|^2 / 12).
      double spread = 0;
      for (const Vec3& v : t) spread += dot(sub(v, p), sub(v, p));
      node.i2 += area * (dot(pc, pc) + spread / 12);
    }
  } else {
    const Node* children[2] = {&node + 1, &nodes[node.right]};
    for (const Node* child : children) {
      const Vec3 shift = sub(child->c, node.c);
      for (int j = 0; j < 3; ++j) {
        node.n[j] += child->n[j];
        for (int k = 0; k < 3; ++k) node.m[3 * j + k] += child->m[3 * j + k] + child->n[j] * shift[k];
      }
      node.area += child->area;
      node.area_abs += child->area_abs;
      node.mabs += child->mabs + child->area * norm(shift);
      // |x - c| <= |x - c_k| + s, and the integral of |x - c_k| is at most
      // sqrt(area_k i2_k) (Cauchy-Schwarz).
      const double sk = norm(shift);
      node.i2 += child->i2 + 2 * sk * std::sqrt(child->area * child->i2) + sk * sk * child->area;
    }
  }
  // The normal cone and the slab about the plane through c along n0 (S18),
  // from the node's own triangles.
  const double nn = norm(node.n);
  node.n0 = {};
  node.slab = 0;
  node.delta = 2;
  if (nn > 0) {
    node.n0 = {node.n[0] / nn, node.n[1] / nn, node.n[2] / nn};
    double delta = 0, slab = 0;
    for (std::uint32_t i = node.begin; i < node.end; ++i) {
      const Points& t = points[i];
      const Vec3 e1 = sub(t[1], t[0]), e2 = sub(t[2], t[0]);
      const Vec3 cr = cross(e1, e2);
      const double len = norm(cr);
      const double alpha = norm(e1) * norm(e2);
      for (const Vec3& v : t) slab = std::max(slab, std::abs(dot(sub(v, node.c), node.n0)));
      if (alpha == 0) continue;  // a point: no area
      if (!(len > 256 * kU * alpha)) {
        delta = 2;  // (nearly) collinear: the normal is unknown, no cone
        break;
      }
      // The computed cross product is within 16u alpha of the exact one, so
      // its direction within 32u alpha / len; the division adds 8u.
      const Vec3 ni = {cr[0] / len, cr[1] / len, cr[2] / len};
      delta = std::max(delta, norm(sub(ni, node.n0)) + 32 * kU * alpha / len + 8 * kU);
    }
    node.delta = std::min(2.0, delta * (1 + 8 * kU));
    node.slab = (slab + 16 * kU * node.r) * (1 + 8 * kU);
  }
  // The sums were rounded: round the bounds up (depth <= 60 additions).
  node.area *= 1 + 128 * kU;
  node.mabs *= 1 + 128 * kU;
  node.i2 = std::min(node.i2 * (1 + 128 * kU), node.area * node.r * node.r);
  node.i1 = std::sqrt(node.area * node.i2) * (1 + 4 * kU);
}

WindingNumber::WindingNumber(std::vector<Vec3> vertices, std::vector<Triangle> triangles) : impl_(new Impl) {
  Impl& m = *impl_;
  m.vertices = std::move(vertices);
  m.triangles = std::move(triangles);
  const auto n = static_cast<std::uint32_t>(m.triangles.size());
  std::vector<Vec3> centroids(n);
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    order[i] = i;
    for (int k = 0; k < 3; ++k)
      centroids[i][k] =
          (m.vertices[m.triangles[i][0]][k] + m.vertices[m.triangles[i][1]][k] + m.vertices[m.triangles[i][2]][k]) / 3;
  }
  if (n == 0) return;
  m.build(order, centroids, 0, n, 0);
  m.points.resize(n);
  m.ids.resize(n);
  m.degenerate.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    m.ids[i] = order[i];
    const Triangle& t = m.triangles[order[i]];
    m.points[i] = {m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]};
    const Points& p = m.points[i];
    m.degenerate[i] =
        orient2d(p[0], p[1], p[2], 0) == 0 && orient2d(p[0], p[1], p[2], 1) == 0 && orient2d(p[0], p[1], p[2], 2) == 0;
  }
  for (std::size_t i = m.nodes.size(); i-- > 0;) m.finish(m.nodes[i]);  // children after parents in pre-order
}

WindingNumber::~WindingNumber() { delete impl_; }
WindingNumber::WindingNumber(WindingNumber&& other) noexcept : impl_(std::exchange(other.impl_, nullptr)) {}
WindingNumber& WindingNumber::operator=(WindingNumber&& other) noexcept {
  if (this != &other) {
    delete impl_;
    impl_ = std::exchange(other.impl_, nullptr);
  }
  return *this;
}

std::size_t WindingNumber::size() const { return impl_ ? impl_->triangles.size() : 0; }

std::uint64_t WindingNumber::full_sums() const { return impl_ ? impl_->full_sums.load(std::memory_order_relaxed) : 0; }

namespace {

// spec/stuffing.md S18: the far field of a node (|q - c| = d > r), to first
// order, and its bound 3 I2 / (d - r)^4 / (4 pi) (I2 the second moment, at
// most A r^2) with the rounding allowance of the expansion's evaluation.
WindingNumber::Estimate far_term(const Node& node, const Vec3& q, double qnorm, const Vec3& dx, double d, double d_lo) {
  const double inv = 1 / d, inv3 = inv * inv * inv;
  const Vec3 u = {dx[0] * inv, dx[1] * inv, dx[2] * inv};
  const std::array<double, 9>& mm = node.m;
  double umu = 0;
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) umu += u[j] * mm[3 * j + k] * u[k];
  const double trace = mm[0] + mm[4] + mm[8];
  const double value = (dot(node.n, dx) * inv3 + (trace - 3 * umu) * inv3) / k4Pi;
  // The distance from q to the node's box (which holds the segments from c
  // to its points), rounded down, when it is larger than d - r.
  double box2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double out = std::max({node.lo[k] - q[k], q[k] - node.hi[k], 0.0});
    box2 += out * out;
  }
  const double ball = d_lo - node.r;
  const double gap = box2 > ball * ball ? std::max(ball, std::sqrt(box2) * (1 - 8 * kU)) : ball;
  const double gap2 = gap * gap;
  // |D^2 f [v, v]| <= min(6 |v|^2, 6 |n.v| |v| + 12 |e.n| |v|^2) / rho^4 (S18),
  // |n.v| <= slab + delta |v|, |e.n| <= kappa; the integral of |v| at most sqrt(A I2).
  double moment = 3 * node.i2;
  if (node.delta < 1) {
    const double height = std::abs(dot(dx, node.n0)) + 16 * kU * d;
    const double kappa = std::min(1.0, (height + node.slab) / gap + node.delta);
    moment = std::min(moment, (3 * (node.slab * node.i1 + node.delta * node.i2) + 6 * kappa * node.i2) * (1 + 32 * kU));
  }
  const double taylor = moment / (gap2 * gap2) / k4Pi;
  const double inv_lo = 1 / d_lo;
  const double allowance =
      512 * kU *
      (node.area_abs * inv_lo * inv_lo +
       4 * (node.mabs + node.area_abs * (node.cnorm + qnorm + node.r)) * inv_lo * inv_lo * inv_lo) /
      k4Pi;
  return {value, taylor * (1 + 16 * kU) + allowance};
}

// The rounding of a sum of m positive bounds, each rounded up: gamma_m.
double gamma_of(double m) { return m * kU / (1 - m * kU); }

}  // namespace

// The solid angles (S17) at q of the triangles at tree positions [begin,
// end), each to add(term): the degenerate ones (w = 0) and the excluded
// input indices (sorted) left out.
template <class Add>
void WindingNumber::Impl::each_solid_angle(std::uint32_t begin, std::uint32_t end, const Vec3& q,
                                           std::span<const std::uint32_t> excluded, Add add) const {
  for (std::uint32_t i = begin; i < end; ++i) {
    if (degenerate[i]) continue;
    if (!excluded.empty() && std::binary_search(excluded.begin(), excluded.end(), ids[i])) continue;
    add(solid_angle(points[i], q));
  }
}

// The walk of the hierarchy from `root` (S17-S18): a node with
// |q - c| (1 - 4u) > beta r gives its far-field term to far(index, term);
// a leaf nearer than that its triangles' solid angles to add(term); an
// inner node nearer than that is opened (left child first).
template <class Far, class Add>
void WindingNumber::Impl::walk(std::uint32_t root, const Vec3& q, double qnorm, double beta,
                               std::span<const std::uint32_t> excluded, Far far, Add add) const {
  std::uint32_t stack[2 * kMaxDepth + 8];
  int top = 0;
  stack[top++] = root;
  while (top > 0) {
    const std::uint32_t index = stack[--top];
    const Node& node = nodes[index];
    const Vec3 dx = sub(node.c, q);
    const double d = norm(dx);
    const double d_lo = d * (1 - 4 * kU);
    if (d_lo > beta * node.r) {
      far(index, far_term(node, q, qnorm, dx, d, d_lo));
    } else if (node.right == 0) {
      each_solid_angle(node.begin, node.end, q, excluded, add);
    } else {
      stack[top++] = node.right;
      stack[top++] = index + 1;
    }
  }
}

// Nodes with |q - c| > beta r in the far field, the rest exactly (S17). The
// sum's own rounding: gamma_m sum|terms| (m the terms).
WindingNumber::Estimate WindingNumber::Impl::run(const Vec3& q, double beta,
                                                 std::span<const std::uint32_t> excluded) const {
  if (!(beta > 1)) throw std::invalid_argument("soup::WindingNumber::estimate: beta must be > 1");
  double sum = 0, sum_abs = 0, error = 0;
  double terms = 0;
  if (nodes.empty()) return {};
  auto add = [&](const Estimate& t) {
    sum += t.value;
    sum_abs += std::abs(t.value);
    error += t.error;
    terms += 1;
  };
  walk(
      0, q, norm(q), beta, excluded, [&](std::uint32_t, const Estimate& t) { add(t); }, add);
  const double g = gamma_of(terms);
  return {sum, (error * (1 + g) + g * sum_abs * (1 + 2 * g)) * (1 + 4 * kU)};
}

WindingNumber::Estimate WindingNumber::Impl::exact(const Vec3& q, std::span<const std::uint32_t> excluded) const {
  double sum = 0, sum_abs = 0, error = 0;
  each_solid_angle(0, static_cast<std::uint32_t>(points.size()), q, excluded, [&](const Estimate& t) {
    sum += t.value;
    sum_abs += std::abs(t.value);
    error += t.error;
  });
  const double g = gamma_of(static_cast<double>(points.size()));
  return {sum, (error * (1 + g) + g * sum_abs * (1 + 2 * g)) * (1 + 4 * kU)};
}

WindingNumber::Estimate WindingNumber::estimate(const Vec3& q) const { return estimate(q, kBeta); }

WindingNumber::Estimate WindingNumber::estimate(const Vec3& q, double beta) const { return impl_->run(q, beta, {}); }

// spec/stuffing.md S18: |w - value| <= error; the difference's rounding:
// compare with error (1 + 4u).
int WindingNumber::certified_sign(const Estimate& e, double threshold) {
  const double margin = e.error * (1 + 4 * kU);
  const double diff = e.value - threshold;
  if (diff >= margin) return 1;
  if (diff < -margin) return -1;
  return 0;
}

WindingNumber::Estimate WindingNumber::direct_bounded(const Vec3& q) const { return impl_->exact(q, {}); }

double WindingNumber::direct(const Vec3& q) const { return impl_->exact(q, {}).value; }

// spec/stuffing.md S18: is w >= threshold (w summed without the excluded
// triangles)? One pass with kSideBeta, then, while the bound does not
// decide, the far node with the largest bound is replaced by its children
// (or its triangles, exactly); with no far node left, a value within the
// bound of the threshold counts as >= (the tie rule).
bool WindingNumber::Impl::at_least(const Vec3& q, std::span<const std::uint32_t> excluded, double threshold) const {
  if (nodes.empty()) return 0 >= threshold;
  struct Far {
    double bound, value;
    std::uint32_t node;
  };
  auto by_bound = [](const Far& x, const Far& y) { return x.bound < y.bound; };
  thread_local std::vector<Far> far;
  far.clear();
  const double qnorm = norm(q);
  double sum = 0, sum_abs = 0, terms = 0;  // every term added or taken off
  double exact_error = 0, exact_terms = 0;
  double far_error = 0;  // >= the sum of the far nodes' bounds: rounded up at each step
  bool heap = false;     // far is a max-heap by bound (after the first pass)
  auto up = [](double x) { return x * (1 + 4 * kU); };
  auto add_exact = [&](const Estimate& t) {
    sum += t.value;
    sum_abs += std::abs(t.value);
    terms += 1;
    exact_error += t.error;
    exact_terms += 1;
  };
  auto add_far = [&](std::uint32_t index, const Estimate& t) {
    sum += t.value;
    sum_abs += std::abs(t.value);
    terms += 1;
    far.push_back({t.error, t.value, index});
    if (heap) std::push_heap(far.begin(), far.end(), by_bound);
    far_error = up(far_error + t.error);
  };
  auto leaf = [&](const Node& node) { each_solid_angle(node.begin, node.end, q, excluded, add_exact); };
  auto open = [&](std::uint32_t root) { walk(root, q, qnorm, kSideBeta, excluded, add_far, add_exact); };
  open(0);
  for (;;) {
    const double g = gamma_of(terms), ge = gamma_of(exact_terms);
    const double bound = (exact_error * (1 + ge) + far_error + g * sum_abs * (1 + 2 * g)) * (1 + 4 * kU);
    if (const int sign = certified_sign({sum, bound}, threshold); sign != 0) return sign > 0;
    if (far.empty()) {
      full_sums.fetch_add(1, std::memory_order_relaxed);
      return true;
    }
    if (!heap) {
      std::make_heap(far.begin(), far.end(), by_bound);
      heap = true;
    }
    std::pop_heap(far.begin(), far.end(), by_bound);
    const Far worst = far.back();
    far.pop_back();
    sum -= worst.value;
    sum_abs += std::abs(worst.value);
    terms += 1;
    far_error = far.empty() ? 0 : up(far_error - worst.bound);
    const Node& node = nodes[worst.node];
    if (node.right == 0) {
      leaf(node);
    } else {
      open(worst.node + 1);
      open(node.right);
    }
  }
}

// spec/stuffing.md S19: the triangles whose closed set holds q, by exact
// predicates, searching the nodes whose box holds q. Degenerate triangles
// (exactly collinear corners) are never found.
std::vector<Hit> WindingNumber::Impl::on_triangles(const Vec3& q) const {
  std::vector<Hit> hits;
  if (nodes.empty()) return hits;
  auto in_box = [&](const Vec3& lo, const Vec3& hi) {
    for (int k = 0; k < 3; ++k)
      if (q[k] < lo[k] || q[k] > hi[k]) return false;
    return true;
  };
  std::uint32_t stack[2 * kMaxDepth + 8];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t index = stack[--top];
    const Node& node = nodes[index];
    if (!in_box(node.lo, node.hi)) continue;
    if (node.right != 0) {
      stack[top++] = node.right;
      stack[top++] = index + 1;
      continue;
    }
    for (std::uint32_t i = node.begin; i < node.end; ++i) {
      const Points& t = points[i];
      Vec3 lo = t[0], hi = t[0];
      for (const Vec3& v : t)
        for (int k = 0; k < 3; ++k) {
          lo[k] = std::min(lo[k], v[k]);
          hi[k] = std::max(hi[k], v[k]);
        }
      if (!in_box(lo, hi)) continue;
      if (orient3d(t[0], t[1], t[2], q) != 0) continue;
      // A projection along which the triangle is not degenerate: try the
      // axes by the size of the (rounded) normal's components.
      const Vec3 nr = cross(sub(t[1], t[0]), sub(t[2], t[0]));
      int axes[3] = {0, 1, 2};
      std::sort(axes, axes + 3, [&](int x, int y) { return std::abs(nr[x]) > std::abs(nr[y]); });
      int axis = -1, o = 0;
      for (const int k : axes)
        if ((o = orient2d(t[0], t[1], t[2], k)) != 0) {
          axis = k;
          break;
        }
      if (axis < 0) continue;  // degenerate
      int e[3], zeros = 0, nonzero = 0;
      bool outside = false;
      for (int j = 0; j < 3; ++j) {
        e[j] = orient2d(t[j], t[(j + 1) % 3], q, axis);
        if (e[j] == -o) outside = true;
        if (e[j] == 0) ++zeros;
      }
      if (outside) continue;
      Hit h{i, axis, 0, 0};
      if (zeros == 1) {
        h.loc = 1;
        for (int j = 0; j < 3; ++j)
          if (e[j] == 0) h.at = j;
      } else if (zeros == 2) {
        h.loc = 2;
        for (int j = 0; j < 3; ++j)
          if (e[j] != 0) nonzero = j;
        h.at = (nonzero + 2) % 3;  // the corner off the one edge q is not on
      }
      hits.push_back(h);
    }
  }
  return hits;
}

// spec/stuffing.md S19: the side of a point on the triangles.
int WindingNumber::Impl::side_on(const Vec3& q, const std::vector<Hit>& hits) const {
  std::vector<std::uint32_t> excluded;
  for (const Hit& h : hits) excluded.push_back(ids[h.pos]);
  std::sort(excluded.begin(), excluded.end());
  // All in one plane?
  const Points& t0 = points[hits[0].pos];
  for (const Hit& h : hits)
    for (const Vec3& v : points[h.pos])
      if (orient3d(t0[0], t0[1], t0[2], v) != 0) return 0;
  const int axis = hits[0].axis;
  const int o0 = orient2d(t0[0], t0[1], t0[2], axis);
  // The signed turns the triangles cover around q in the plane, and the
  // rays that bound their cones (+1 at the corner after q in the triangle's
  // own order, -1 at the corner before q).
  double turns = 0;
  std::vector<std::pair<Vec3, int>> events;
  for (const Hit& h : hits) {
    const Points& t = points[h.pos];
    const int s = orient2d(t[0], t[1], t[2], axis) * o0;
    if (h.loc == 0) {
      turns += s;
    } else if (h.loc == 1) {
      turns += s * 0.5;
      events.emplace_back(t[(h.at + 1) % 3], 1);
      events.emplace_back(t[h.at], -1);
    } else {
      const Vec3& next = t[(h.at + 1) % 3];
      const Vec3& prev = t[(h.at + 2) % 3];
      const Vec3 u = sub(next, q), v = sub(prev, q);
      turns += s * std::atan2(norm(cross(u, v)), dot(u, v)) / (2 * kPi);
      events.emplace_back(next, 1);
      events.emplace_back(prev, -1);
    }
  }
  // The cover is uniform iff every ray's events cancel. Rays q->a and q->b
  // are one iff q, a, b are collinear (exactly, in the plane's projection)
  // and a - q, b - q have the same signs (exact for rounded differences).
  auto same_ray = [&](const Vec3& a, const Vec3& b) {
    if (orient2d(q, a, b, axis) != 0) return false;
    for (int k = 0; k < 3; ++k) {
      const double x = a[k] - q[k], y = b[k] - q[k];
      if ((x > 0) != (y > 0) || (x < 0) != (y < 0)) return false;
    }
    return true;
  };
  std::vector<bool> done(events.size(), false);
  for (std::size_t i = 0; i < events.size(); ++i) {
    if (done[i]) continue;
    int net = 0;
    for (std::size_t j = i; j < events.size(); ++j)
      if (!done[j] && same_ray(events[i].first, events[j].first)) {
        done[j] = true;
        net += events[j].second;
      }
    if (net != 0) return 0;  // not a uniform cover: an edge of the surface through q
  }
  const double m = std::round(turns);
  // Limits: w̄ - m/2 on the side the first triangle's normal points to, w̄ + m/2 on the other.
  const bool front = at_least(q, excluded, 0.5 + m / 2);
  const bool back = at_least(q, excluded, 0.5 - m / 2);
  if (front != back) return 0;
  return front ? -1 : 1;
}

// spec/stuffing.md S18, S19.
int WindingNumber::side(const Vec3& q) const {
  const std::vector<Hit> hits = impl_->on_triangles(q);
  if (!hits.empty()) return impl_->side_on(q, hits);
  return impl_->at_least(q, {}, 0.5) ? -1 : 1;
}

}  // namespace bccmis::soup
