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
  // and (i, j, l): between the components of ik and il orthogonal to ij.
  static constexpr int kEdges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                       {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  std::array<long double, 6> out{};
  for (int e = 0; e < 6; ++e) {
    const auto [i, j, k, l] = kEdges[e];
    const V axis = sub(t[j], t[i]);
    const V nk = cross(axis, sub(t[k], t[i])), nl = cross(axis, sub(t[l], t[i]));
    out[static_cast<std::size_t>(e)] = std::clamp(dot(nk, nl) / std::sqrt(dot(nk, nk) * dot(nl, nl)), -1.0L, 1.0L);
  }
  return out;
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
