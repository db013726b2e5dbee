// spec/distributed.md D10: the lattice of a rank (L_r) from the leaves it
// knows (N_r), and the condition under which its tetrahedra are G's.
#include "bccmis/distributed/local_lattice.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "bccmis/balance.h"
#include "bccmis/geometry.h"

namespace bccmis::distributed {

namespace {

/// The level of the cell centered at c: a level-l center's coordinates are
/// odd multiples of 2^(L-l) (d3/point.h: a level-l cube has side 2^(L+1-l)).
int level_of_center(const d3::LatticeSize& size, const d3::Point& c) {
  const auto low = [](std::int64_t v) { return v > 0 ? std::countr_zero(static_cast<std::uint64_t>(v)) : 64; };
  const int z = low(c.x);
  if (z > size.L || low(c.y) != z || low(c.z) != z)
    throw std::invalid_argument("local_lattice: " + d3::to_string(c) +
                                " is not a cell center (spec/distributed.md D10)");
  return size.L - z;
}

}  // namespace

d3::fast::Lattice local_lattice(const d3::LatticeSize& size, std::span<const d3::Point> known) {
  d3::fast::Lattice l(size);
  // The proper ancestors of the known leaves, level by level: a level-k
  // ancestor is a cell of l once the levels below k are refined (or, refined
  // by an earlier cascade, no longer a leaf: its children are there).
  std::vector<std::vector<d3::Point>> ancestors(static_cast<std::size_t>(size.L) + 1);
  for (const d3::Point& c : known) {
    const int level = level_of_center(size, c);
    for (int k = 0; k < level; ++k) {
      const std::int64_t s = d3::cell_side(size, k);
      ancestors[static_cast<std::size_t>(k)].push_back({c.x / s * s + s / 2, c.y / s * s + s / 2, c.z / s * s + s / 2});
    }
  }
  for (std::vector<d3::Point>& cells : ancestors) {
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    for (const d3::Point& a : cells)
      if (l.is_center(a)) refine_balanced(l, a, Balance::Edge);
    cells = {};
  }
  return l;
}

std::optional<d3::Point> first_open(const d3::fast::Lattice& l, std::span<const d3::Point> known,
                                    std::span<const d3::Point> stuffed) {
  const auto is_known = [&known](const d3::Point& u) { return std::binary_search(known.begin(), known.end(), u); };
  for (const d3::Point& u : stuffed) {
    bool open = !is_known(u) || !l.is_center(u);
    if (!open) for_each_touching_neighbor(l, u, [&](const d3::Point& x) { open = open || !is_known(x); });
    if (open) return u;
  }
  return std::nullopt;
}

}  // namespace bccmis::distributed
