#include "bccmis/d3/graph.h"

#include <string>

namespace bccmis::d3 {

Graph make_lattice(const LatticeSize& size) {
  validate_lattice_size(size);
  const std::int64_t S = level0_side(size);
  Graph g;
  g.size = size;
  for (std::int64_t i = 0; i <= size.W; ++i)
    for (std::int64_t j = 0; j <= size.H; ++j)
      for (std::int64_t k = 0; k <= size.D; ++k) g.N.insert({i * S, j * S, k * S});
  for (std::int64_t i = 0; i < size.W; ++i)
    for (std::int64_t j = 0; j < size.H; ++j)
      for (std::int64_t k = 0; k < size.D; ++k) {
        const Point c{i * S + S / 2, j * S + S / 2, k * S + S / 2};
        g.C.insert(c);
        g.level[c] = 0;
        for (std::int64_t di = 0; di <= 1; ++di)
          for (std::int64_t dj = 0; dj <= 1; ++dj)
            for (std::int64_t dk = 0; dk <= 1; ++dk) {
              const Point p{(i + di) * S, (j + dj) * S, (k + dk) * S};
              g.neighbors[c].insert(p);
              g.neighbors[p].insert(c);
            }
      }
  return g;
}

}  // namespace bccmis::d3

namespace bccmis {
template struct BasicGraph<d3::Point, d3::LatticeSize>;
}  // namespace bccmis
