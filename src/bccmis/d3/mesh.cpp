// bccmis::d3: extraction of the graded BCC tetrahedral mesh (spec/mesh3d.md),
// its exact orientation, dihedral angles and quality.
#include "bccmis/d3/mesh.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>

#include "bccmis/d3/detail/tetrahedra.h"
#include "bccmis/d3/geometry.h"
#include "bccmis/d3/lattice.h"

namespace bccmis::d3 {
namespace {

bool fits_41_bits(std::int64_t v) { return v > -(std::int64_t{1} << 41) && v < (std::int64_t{1} << 41); }

// The three difference vectors b - a, c - a, d - a (each component fits:
// coordinates lie in [0, 2^62]).
std::array<std::array<std::int64_t, 3>, 3> differences(const Point& a, const Point& b, const Point& c, const Point& d) {
  return {{{b.x - a.x, b.y - a.y, b.z - a.z}, {c.x - a.x, c.y - a.y, c.z - a.z}, {d.x - a.x, d.y - a.y, d.z - a.z}}};
}

template <class T>
T det3(const std::array<std::array<std::int64_t, 3>, 3>& m) {
  auto e = [&](int i, int j) { return T(m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]); };
  return e(0, 0) * (e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1)) - e(0, 1) * (e(1, 0) * e(2, 2) - e(1, 2) * e(2, 0)) +
         e(0, 2) * (e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0));
}

// mpz_class converts from long, which is 64 bits wide on the platforms bccmis builds on.
static_assert(sizeof(long) == sizeof(std::int64_t));
mpz_class big(std::int64_t v) { return mpz_class(static_cast<long>(v)); }

template <>
mpz_class det3<mpz_class>(const std::array<std::array<std::int64_t, 3>, 3>& m) {
  auto e = [&](int i, int j) { return big(m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]); };
  mpz_class r = e(0, 0) * (e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1));
  r -= e(0, 1) * (e(1, 0) * e(2, 2) - e(1, 2) * e(2, 0));
  r += e(0, 2) * (e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0));
  return r;
}

bool small(const std::array<std::array<std::int64_t, 3>, 3>& m) {
  for (const auto& row : m)
    for (const std::int64_t v : row)
      if (!fits_41_bits(v)) return false;
  return true;
}

}  // namespace

int orientation(const Point& a, const Point& b, const Point& c, const Point& d) {
  const auto m = differences(a, b, c, d);
  if (small(m)) {
    const Int128 v = det3<Int128>(m);  // each product < 2^123, the sum < 2^126
    return (v > 0) - (v < 0);
  }
  return sgn(det3<mpz_class>(m));
}

Int128 six_volume(const Tet& t) {
  const auto m = differences(t[0], t[1], t[2], t[3]);
  if (!small(m)) throw std::overflow_error("six_volume: coordinate differences of 2^41 or more");
  return det3<Int128>(m);
}

// spec/mesh3d.md M1-M4 (the rule in d3/detail/tetrahedra.h)
std::vector<Tet> tetrahedra(const Graph& g) { return detail::tetrahedra_of(g); }

TetMesh index_mesh(const Graph& g, const std::vector<Tet>& tets) {
  TetMesh mesh;
  for (const Tet& t : tets) mesh.vertices.insert(mesh.vertices.end(), t.begin(), t.end());
  std::sort(mesh.vertices.begin(), mesh.vertices.end());
  mesh.vertices.erase(std::unique(mesh.vertices.begin(), mesh.vertices.end()), mesh.vertices.end());
  mesh.kind.reserve(mesh.vertices.size());
  for (const Point& v : mesh.vertices)
    mesh.kind.push_back(static_cast<std::uint8_t>(g.is_node(v)     ? VertexKind::node
                                                  : g.is_center(v) ? VertexKind::center
                                                                   : VertexKind::hull));
  mesh.tets.reserve(tets.size());
  mesh.level.reserve(tets.size());
  for (const Tet& t : tets) {
    mesh.level.push_back(g.is_center(t[0]) ? g.level_of(t[0]) : -1);
    std::array<std::uint32_t, 4> ids{};
    for (std::size_t i = 0; i < 4; ++i)
      ids[i] = static_cast<std::uint32_t>(std::lower_bound(mesh.vertices.begin(), mesh.vertices.end(), t[i]) -
                                          mesh.vertices.begin());
    mesh.tets.push_back(ids);
  }
  return mesh;
}

namespace {

// The angles, once for lattice points and once for points in space.
long double coordinate(const Point& p, int i) { return static_cast<long double>(i == 0 ? p.x : i == 1 ? p.y : p.z); }
long double coordinate(const Vec3& p, int i) { return p[static_cast<std::size_t>(i)]; }

template <class P>
std::array<long double, 6> dihedral_cosines_impl(const std::array<P, 4>& t) {
  using V = std::array<long double, 3>;
  auto sub = [](const P& a, const P& b) {
    return V{coordinate(a, 0) - coordinate(b, 0), coordinate(a, 1) - coordinate(b, 1),
             coordinate(a, 2) - coordinate(b, 2)};
  };
  auto cross = [](const V& a, const V& b) {
    return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto dot = [](const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  // The dihedral angle at edge (i, j) is the angle between the faces (i, j, k)
  // and (i, j, l): between the components of ik and il orthogonal to ij, the
  // cosine dot(n_k, n_l) / sqrt(dot(n_k, n_k) dot(n_l, n_l)) of n_k = ij x ik
  // and n_l = ij x il, for the edges 01, 02, 03, 12, 13, 23 in turn. Edges
  // through a common vertex share these cross products up to sign, and
  // b x a = -(a x b) exactly in floating point (each component is the other's
  // difference of the same two products, negated), as are a dot with one
  // side negated and a quotient with a negated numerator: so 8 cross products
  // serve the 12, with the bits of computing each edge's own.
  const V d01 = sub(t[1], t[0]), d02 = sub(t[2], t[0]), d03 = sub(t[3], t[0]);
  const V d12 = sub(t[2], t[1]), d13 = sub(t[3], t[1]), d10 = sub(t[0], t[1]);
  const V d23 = sub(t[3], t[2]), d20 = sub(t[0], t[2]), d21 = sub(t[1], t[2]);
  const V a = cross(d01, d02), b = cross(d01, d03), c = cross(d02, d03);  // at vertex 0
  const V d = cross(d12, d10), e = cross(d12, d13), f = cross(d13, d10);  // at vertex 1
  const V g = cross(d23, d20), h = cross(d23, d21);                       // at edge 23
  const long double na = dot(a, a), nb = dot(b, b), nc = dot(c, c), nd = dot(d, d), ne = dot(e, e), nf = dot(f, f);
  const auto cosine = [](long double along, long double nk, long double nl) {
    return std::clamp(along / std::sqrt(nk * nl), -1.0L, 1.0L);
  };
  return {cosine(dot(a, b), na, nb),                 // 01: n_k = a, n_l = b
          cosine(-dot(a, c), na, nc),                // 02: -a, c
          cosine(dot(b, c), nb, nc),                 // 03: -b, -c
          cosine(dot(d, e), nd, ne),                 // 12: d, e
          cosine(-dot(f, e), nf, ne),                // 13: f, -e
          cosine(dot(g, h), dot(g, g), dot(h, h))};  // 23: g, h
}

template <class P>
std::array<double, 6> dihedral_angles_impl(const std::array<P, 4>& t) {
  std::array<double, 6> out{};
  const auto c = dihedral_cosines_impl(t);
  for (std::size_t e = 0; e < 6; ++e) out[e] = dihedral_angle(c[e]);
  return out;
}

}  // namespace

std::array<double, 6> dihedral_angles(const Tet& t) { return dihedral_angles_impl(t); }
std::array<double, 6> dihedral_angles(const std::array<Vec3, 4>& t) { return dihedral_angles_impl(t); }
std::array<long double, 6> dihedral_cosines(const std::array<Vec3, 4>& t) { return dihedral_cosines_impl(t); }
double dihedral_angle(long double cosine) { return static_cast<double>(std::acos(cosine) * 180.0L / std::acos(-1.0L)); }

MeshQuality mesh_quality(const std::vector<Tet>& tets) {
  MeshQuality q;
  q.tetrahedra = tets.size();
  std::vector<Point> vertices;
  std::map<std::array<Point, 3>, int> triangles;
  q.min_dihedral = tets.empty() ? 0 : 180;
  for (const Tet& t : tets) {
    vertices.insert(vertices.end(), t.begin(), t.end());
    for (int skip = 0; skip < 4; ++skip) {
      std::array<Point, 3> f{};
      for (int i = 0, n = 0; i < 4; ++i)
        if (i != skip) f[n++] = t[i];
      std::sort(f.begin(), f.end());
      ++triangles[f];
    }
    for (const double a : dihedral_angles(t)) {
      q.min_dihedral = std::min(q.min_dihedral, a);
      q.max_dihedral = std::max(q.max_dihedral, a);
      ++q.histogram[static_cast<std::size_t>(std::lround(a / 15.0))];
    }
  }
  std::sort(vertices.begin(), vertices.end());
  q.vertices = static_cast<std::size_t>(std::unique(vertices.begin(), vertices.end()) - vertices.begin());
  for (const auto& [f, n] : triangles) q.boundary_triangles += n == 1 ? 1 : 0;
  return q;
}

}  // namespace bccmis::d3
