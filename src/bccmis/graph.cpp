#include "bccmis/graph.h"

#include <string>

namespace bccmis {

template struct BasicGraph<Point, LatticeSize>;

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
