#include "bccmis/graph.h"

#include <string>

namespace bccmis {

template struct BasicGraph<Point, LatticeSize>;

// Built by appending: g++ 12 at -O3 gives a false -Wrestrict (GCC bug 105651)
// on `"literal" + std::string` once inlined.
std::string to_string(const Point& p) {
  std::string t = "(";
  t += std::to_string(p.x);
  t += ", ";
  t += std::to_string(p.y);
  t += ')';
  return t;
}

void validate_lattice_size(const LatticeSize& size) {
  if (size.W < 1) throw LatticeError("lattice width W must be >= 1, got " + std::to_string(size.W));
  if (size.H < 1) throw LatticeError("lattice height H must be >= 1, got " + std::to_string(size.H));
  if (size.L < 0) throw LatticeError("maximum level L must be >= 0, got " + std::to_string(size.L));
  // S = 2^(L+1) <= 2^62 is necessary for W*S <= 2^62 with W >= 1.
  if (size.L > 61)
    throw LatticeError("maximum level L = " + std::to_string(size.L) +
                       " makes the level-0 cell side 2^(L+1) exceed 2^62");
  const std::int64_t S = level0_side(size);
  const std::int64_t max_cells = kMaxDomainSide / S;  // W*S <= 2^62  <=>  W <= 2^62 / S
  if (size.W > max_cells)
    throw LatticeError("lattice width W = " + std::to_string(size.W) + " with L = " + std::to_string(size.L) +
                       " makes the domain side W*2^(L+1) exceed 2^62");
  if (size.H > max_cells)
    throw LatticeError("lattice height H = " + std::to_string(size.H) + " with L = " + std::to_string(size.L) +
                       " makes the domain side H*2^(L+1) exceed 2^62");
}

Graph make_lattice(const LatticeSize& size) {
  validate_lattice_size(size);
  const std::int64_t S = level0_side(size);
  Graph g;
  g.size = size;
  for (std::int64_t i = 0; i <= size.W; ++i)
    for (std::int64_t j = 0; j <= size.H; ++j) g.N.insert({i * S, j * S});
  for (std::int64_t i = 0; i < size.W; ++i)
    for (std::int64_t j = 0; j < size.H; ++j) {
      const Point c{i * S + S / 2, j * S + S / 2};
      g.C.insert(c);
      g.level[c] = 0;
      for (const Point p : {Point{i * S, j * S}, Point{(i + 1) * S, j * S}, Point{i * S, (j + 1) * S},
                            Point{(i + 1) * S, (j + 1) * S}}) {
        g.neighbors[c].insert(p);
        g.neighbors[p].insert(c);
      }
    }
  return g;
}

}  // namespace bccmis
