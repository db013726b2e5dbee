// Isosurface stuffing (spec/stuffing.md), phase by phase: the fast path
// (d3::fast::Lattice, flat arrays) against the reference (d3::Graph, ordered
// maps) on the built-in sphere and torus. A plain program: one run per shape,
// level and implementation; the reference only while its previous level
// suggests it finishes within the budget. bench/RESULTS.md section 15.
//
//   bench_stuff [min_level max_level] [--budget SECONDS] [--verify] [--no-reference]
//
// Where both run, the two paths must give the same mesh (vertices bit for
// bit, kinds, tetrahedra, levels, counts); the exit status is 1 otherwise.
// --verify also fails when the reference ran at no level.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "bccmis/stuff/stuff.h"

namespace {

using namespace bccmis::stuff;

bool same(const Stuffed& a, const Stuffed& b) {
  const auto &m = a.mesh, &n = b.mesh;
  if (m.vertices.size() != n.vertices.size() || m.tets != n.tets || m.kind != n.kind || m.level != n.level)
    return false;
  if (a.cut_points != b.cut_points || a.warped != b.warped || a.lattice_tetrahedra != b.lattice_tetrahedra)
    return false;
  return m.vertices.empty() ||
         std::memcmp(m.vertices.data(), n.vertices.data(), m.vertices.size() * sizeof(m.vertices[0])) == 0;
}

void print(const char* shape, int level, const char* impl, const Stuffed& s, const PhaseTimes& t) {
  std::printf("%-7s L%-2d %-9s %10zu %10zu %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f\n", shape, level, impl,
              s.mesh.tets.size(), s.mesh.vertices.size(), t.lattice, t.mesh, t.cut, t.warp, t.stencils, t.total());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  int lo = 4, hi = 7;
  double budget = 60;
  bool verify = false, reference = true;
  int positional = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--verify")
      verify = true;
    else if (a == "--no-reference")
      reference = false;
    else if (a == "--budget" && i + 1 < argc)
      budget = std::atof(argv[++i]);
    else if (positional < 2 && !a.empty() && a[0] != '-')
      (positional++ == 0 ? lo : hi) = std::atoi(a.c_str());
    else {
      std::fprintf(stderr, "usage: bench_stuff [min_level max_level] [--budget SECONDS] [--verify] [--no-reference]\n");
      return 2;
    }
  }
  struct Named {
    const char* name;
    std::unique_ptr<Shape> shape;
  };
  Named shapes[] = {{"sphere", make_sphere({0, 0, 0}, 1)}, {"torus", make_torus({0, 0, 0}, 1, 0.4)}};
  std::printf("%-7s %-3s %-9s %10s %10s %9s %9s %9s %9s %9s %9s\n", "shape", "L", "impl", "tets", "vertices", "lattice",
              "mesh", "cut", "warp", "stencils", "total");
  bool ok = true;
  int compared = 0;
  for (const Named& n : shapes) {
    double previous = 0;  // the reference's time at the level before
    for (int L = lo; L <= hi; ++L) {
      StuffOptions o;
      o.max_level = L;
      PhaseTimes tf;
      const Stuffed fast = stuff_shape(*n.shape, o, Impl::fast, &tf);
      print(n.name, L, "fast", fast, tf);
      // Each level has four to six times the tetrahedra of the one before.
      const bool run_reference = reference && previous * 5 < budget;
      if (!run_reference) continue;
      PhaseTimes tr;
      const Stuffed ref = stuff_shape(*n.shape, o, Impl::reference, &tr);
      print(n.name, L, "reference", ref, tr);
      previous = tr.total();
      std::printf("%-7s L%-2d speedup   %.1fx%s\n", n.name, L, tr.total() / tf.total(),
                  same(fast, ref) ? ", same mesh" : ", MESHES DIFFER");
      if (!same(fast, ref)) ok = false;
      ++compared;
    }
  }
  if (!ok) std::fprintf(stderr, "bench_stuff: the fast and reference meshes differ\n");
  if (verify && compared == 0) {
    std::fprintf(stderr, "bench_stuff: --verify, but the reference ran at no level\n");
    return 1;
  }
  return ok ? 0 : 1;
}
