// S12 of spec/stuffing.md: the exact orientation of four points, which the
// stencils use to orient every output tetrahedron.
#include <gmpxx.h>

#include <cmath>
#include <limits>

#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

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

}  // namespace bccmis::stuff
