// Memory of the 3D lattices: bytes per cell of the reference (d3::Graph on
// std::set / std::map), of the fast lattice (d3::fast::Lattice) and of a CGAL
// Triangulation_3 holding the same tetrahedra (the tet-soup loader of the 3D
// checker's layer 6, exact kernel Epeck: invariants/cgal/
// tetrahedralization_check.h, the only CGAL translation unit involved).
//
//   reference  what operator new hands out (malloc_usable_size of every live
//              block; the global operator new of this program counts:
//              tests/testing/counting_allocator.h) for
//              the d3::Graph of the state (d3::fast::Lattice::to_graph(): the same
//              containers a d3::Graph refined step by step holds);
//   fast       d3::fast::Lattice::memory_bytes() (pools and position table,
//              capacity), and the memory_bytes() of a copy of the lattice
//              (a copy's pools have no spare capacity; from 1 MiB up they
//              are mappings, which operator new does not see:
//              spec/lattice3d.md §9.8);
//   cgal       the counted heap of the loaded triangulation while it is
//              alive (the input tets and every temporary of the load freed
//              or not counted).
//
// States: a uniform W x H x D lattice refined level by level to level L
// (every cell), and the ball of bench_p8est (bench/d3/local_feature.h; graded).
// A plain program, one run. Exit 1 when the triangulation does not load with
// one cell per tet, or a count is empty (checked on every state).
//
//   d3_bench_memory [--smoke]
//
// Numbers and the command: bench/RESULTS.md, "3D memory".
#include <malloc.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bccmis/d3/lattice.h"
#include "bccmis/d3/mesh.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/invariants/cgal/d3/tetrahedralization_check.h"
#include "local_feature.h"
#include "testing/counting_allocator.h"

namespace {

using namespace bccmis;

std::size_t live_bytes() { return bccmis::testing::alloc::live_bytes.load(); }

// Measures one state; returns false on a failed check.
bool measure(const std::string& name, const d3::fast::Lattice& g) {
  const double cells = static_cast<double>(g.cell_count());
  // The fast lattice's held data: the blocks of a copy (no spare capacity).
  const std::size_t fast_heap = d3::fast::Lattice(g).memory_bytes();
  std::size_t reference_bytes = 0;
  const std::size_t before_graph = live_bytes();
  const d3::Graph graph = g.to_graph();
  reference_bytes = live_bytes() - before_graph;
  const std::vector<d3::Tet> tets = d3::tetrahedra(graph);
  std::size_t cgal_bytes = 0;
  const std::size_t before_cgal = live_bytes();
  const std::optional<std::size_t> loaded =
      d3::hold_triangulation(tets, [&](std::size_t) { cgal_bytes = live_bytes() - before_cgal; });
  if (loaded != tets.size()) {
    std::printf("%s: FAILED: the CGAL triangulation has %zu cells for %zu tets\n", name.c_str(), loaded.value_or(0),
                tets.size());
    return false;
  }
  if (cgal_bytes == 0 || reference_bytes == 0 || fast_heap == 0) {
    std::printf("%s: FAILED: a count is empty (reference %zu, fast %zu, cgal %zu bytes)\n", name.c_str(),
                reference_bytes, fast_heap, cgal_bytes);
    return false;
  }
  const double fast_b = static_cast<double>(g.memory_bytes()) / cells;
  const double cgal_b = static_cast<double>(cgal_bytes) / cells;
  std::printf(
      "%-22s %9zu cells %10zu tets | reference %7.0f B/cell | fast %6.0f B/cell (heap %6.0f) | cgal %7.0f B/cell "
      "(%5.0f B/tet) | fast/cgal %.3f | reference/cgal %.2f\n",
      name.c_str(), g.cell_count(), tets.size(), static_cast<double>(reference_bytes) / cells, fast_b,
      static_cast<double>(fast_heap) / cells, cgal_b,
      static_cast<double>(cgal_bytes) / static_cast<double>(tets.size()), fast_b / cgal_b,
      static_cast<double>(reference_bytes) / static_cast<double>(cgal_bytes));
  std::fflush(stdout);
  return true;
}

d3::fast::Lattice uniform(const d3::LatticeSize& size) {
  d3::fast::Lattice g(size);
  for (int l = 0; l < size.L; ++l)
    for (const d3::Point& c : g.cells()) g.refine(c);
  return g;
}

}  // namespace

int main(int argc, char** argv) {
  const bool smoke = argc > 1 && std::strcmp(argv[1], "--smoke") == 0;
  std::vector<d3::LatticeSize> uniforms = {{2, 1, 1, 3}, {2, 2, 2, 3}, {4, 4, 2, 3}, {2, 2, 1, 5}};
  struct Ball {
    d3::LatticeSize size;
    double radius;
  };
  std::vector<Ball> balls = {{{4, 2, 2, 8}, 22.0}, {{4, 2, 2, 8}, 50.0}};
  if (smoke) {
    uniforms = {{2, 1, 1, 2}};
    balls = {{{2, 1, 1, 4}, 5.0}};
  }
  bool ok = true;
  for (const d3::LatticeSize& s : uniforms)
    ok &= measure("uniform " + std::to_string(s.W) + "x" + std::to_string(s.H) + "x" + std::to_string(s.D) + " L" +
                      std::to_string(s.L),
                  uniform(s));
  for (const Ball& b : balls) {
    const d3::bench::LocalFeature<d3::fast::Lattice> ball(b.size, b.radius, 1);
    ok &= measure("ball r=" + std::to_string(static_cast<int>(b.radius)), ball.state());
  }
  return ok ? 0 : 1;
}
