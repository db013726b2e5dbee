// Writes a stuffed built-in shape as a Medit .mesh on standard output, for
// the pictures of `bccmis render` (docs/stuff-*.svg, tests/cli.cmake):
//   stuffed_example sphere|torus MAX_LEVEL CELLS
// sphere: radius 1 around the origin; torus: R = 1, r = 0.4 around the z axis.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include "bccmis/d3/mesh.h"
#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/stuff.h"

int main(int argc, char** argv) {
  using namespace bccmis;
  if (argc != 4) {
    std::fprintf(stderr, "usage: stuffed_example sphere|torus MAX_LEVEL CELLS\n");
    return 2;
  }
  const std::string name = argv[1];
  std::unique_ptr<stuff::Shape> shape;
  if (name == "sphere") shape = stuff::make_sphere({0, 0, 0}, 1);
  if (name == "torus") shape = stuff::make_torus({0, 0, 0}, 1, 0.4);
  if (!shape) {
    std::fprintf(stderr, "stuffed_example: unknown shape '%s'\n", argv[1]);
    return 2;
  }
  stuff::StuffOptions o;
  o.max_level = std::atoi(argv[2]);
  o.cells = std::atoi(argv[3]);
  const stuff::Fit fit = stuff::fit_lattice(shape->bounds(), o);
  const d3::Graph3 g = stuff::background(*shape, fit, o);
  const stuff::Stuffed s = stuff::stuff(*shape, fit, g, o);
  d3::write_medit(std::cout, s.mesh);
  return std::cout.good() ? 0 : 1;
}
