#include "bccmis/point.h"

#include <cstddef>
#include <string>

#include "bccmis/d3/point.h"

namespace bccmis {
namespace {

// One check for every dimension: each extent >= 1, L >= 0, and each domain
// side extent*S at most 2^62; the message names the offending value.
template <class Dim>
void validate(const BasicLatticeSize<Dim>& size) {
  const auto extents = size.extents();
  for (std::size_t i = 0; i < extents.size(); ++i)
    if (extents[i] < 1)
      throw LatticeError(std::string("lattice ") + Dim::extent_names[i] + " must be >= 1, got " +
                         std::to_string(extents[i]));
  if (size.L < 0) throw LatticeError("maximum level L must be >= 0, got " + std::to_string(size.L));
  // S = 2^(L+1) <= 2^62 is necessary for W*S <= 2^62 with W >= 1.
  if (size.L > 61)
    throw LatticeError("maximum level L = " + std::to_string(size.L) + " makes the level-0 " + Dim::box +
                       " side 2^(L+1) exceed 2^62");
  const std::int64_t max_boxes = kMaxDomainSide / level0_side(size);  // W*S <= 2^62  <=>  W <= 2^62 / S
  for (std::size_t i = 0; i < extents.size(); ++i)
    if (extents[i] > max_boxes)
      throw LatticeError(std::string("lattice ") + Dim::extent_names[i] + " = " + std::to_string(extents[i]) +
                         " with L = " + std::to_string(size.L) + " makes the domain " +
                         Dim::domain_side(Dim::extent_names[i], extents[i]) + "*2^(L+1) exceed 2^62");
}

}  // namespace

void validate_lattice_size(const LatticeSize& size) { validate(size); }

void d3::validate_lattice_size(const d3::LatticeSize& size) { validate(size); }

}  // namespace bccmis
