#include "bccmis/d3/point.h"

#include <string>

namespace bccmis::d3 {

std::string to_string(const Point& p) {
  std::string t = "(";
  t += std::to_string(p.x);
  t += ", ";
  t += std::to_string(p.y);
  t += ", ";
  t += std::to_string(p.z);
  t += ')';
  return t;
}

void validate_lattice_size(const LatticeSize& size) {
  if (size.W < 1) throw LatticeError("lattice width W must be >= 1, got " + std::to_string(size.W));
  if (size.H < 1) throw LatticeError("lattice height H must be >= 1, got " + std::to_string(size.H));
  if (size.D < 1) throw LatticeError("lattice depth D must be >= 1, got " + std::to_string(size.D));
  if (size.L < 0) throw LatticeError("maximum level L must be >= 0, got " + std::to_string(size.L));
  // S = 2^(L+1) <= 2^62 is necessary for W*S <= 2^62 with W >= 1.
  if (size.L > 61)
    throw LatticeError("maximum level L = " + std::to_string(size.L) +
                       " makes the level-0 cube side 2^(L+1) exceed 2^62");
  const std::int64_t max_cubes = kMaxDomainSide / level0_side(size);  // W*S <= 2^62  <=>  W <= 2^62 / S
  const struct {
    const char* name;
    std::int64_t count;
  } extents[] = {{"width W", size.W}, {"height H", size.H}, {"depth D", size.D}};
  for (const auto& [name, count] : extents)
    if (count > max_cubes)
      throw LatticeError(std::string("lattice ") + name + " = " + std::to_string(count) +
                         " with L = " + std::to_string(size.L) + " makes the domain extent " + std::to_string(count) +
                         "*2^(L+1) exceed 2^62");
}

}  // namespace bccmis::d3
