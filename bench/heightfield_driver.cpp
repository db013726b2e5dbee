// heightfield_driver: `bccmis heightfield DEM -W 1 -H 1 -L L --tolerance T
// --impl fast --obj OBJ` as a sequence of library calls on the fast lattice
// only (no reference Graph), phase by phase: CPU time of the process per
// phase, and total / tessellate (bench/RESULTS.md, "Height-field output
// paths").
//
//   heightfield_driver DEM L TOLERANCE OBJ [--check]
//
// With --check, also builds the reference Graph of the result and checks
// that its mesh error and OBJ text equal the fast lattice's (exit 1 if not).
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>

#include "bccmis/apps/heightfield.h"
#include "bccmis/apps/image.h"
#include "bccmis/apps/triangulate.h"
#include "bccmis/fast/lattice.h"
#include "bccmis/io/obj.h"

namespace {

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace bccmis;
  if (argc < 5) {
    std::fprintf(stderr, "usage: heightfield_driver DEM L TOLERANCE OBJ [--check]\n");
    return 2;
  }
  const bool check = argc > 5 && std::string_view(argv[5]) == "--check";
  const double t0 = cpu_seconds();
  double t = t0;
  auto phase = [&](const char* name) {
    const double now = cpu_seconds();
    std::fprintf(stderr, "%-12s cpu %8.4f s\n", name, now - t);
    t = now;
  };
  std::ifstream in(argv[1], std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  const HeightField field = parse_height_field(text.str(), argv[1]);
  const LatticeSize size{1, 1, std::atoi(argv[2])};
  const HeightSampler sampler(field, size, 1.0);
  TessellateSettings settings;
  settings.tolerance = std::atof(argv[3]);
  phase("read");
  fast::Lattice g(size);
  const TessellateReport report = tessellate(g, sampler, settings);
  const double tessellate_cpu = cpu_seconds() - t;
  phase("tessellate");
  const MeshError error = mesh_error(g, sampler);
  phase("mesh_error");
  const TriangleMesh mesh = triangulate(g, [&](const Point& p) { return sampler.at(p); });
  phase("triangulate");
  {
    std::ofstream out(argv[4], std::ios::binary | std::ios::trunc);
    io::write_obj(out, mesh, "bccmis heightfield");
    if (!out.flush()) return 2;
  }
  phase("write obj");
  const double total = cpu_seconds() - t0;
  std::fprintf(stderr, "total        cpu %8.4f s  cells %zu  operations %zu  max_error %.9g  total / tessellate %.2f\n",
               total, g.cell_count(), report.refinements + report.coarsenings, error.max_abs, total / tessellate_cpu);
  if (check) {
    const Graph reference = g.to_graph();
    const MeshError e = mesh_error(reference, sampler);
    const TriangleMesh m = triangulate(reference, [&](const Point& p) { return sampler.at(p); });
    const bool same = e.max_abs == error.max_abs && e.rms == error.rms && e.pixels == error.pixels &&
                      e.worst_cell == error.worst_cell &&
                      io::format_obj(m, "bccmis heightfield") == io::format_obj(mesh, "bccmis heightfield");
    std::fprintf(stderr, "check        %s\n", same ? "the reference Graph gives the same error and OBJ" : "DIFFERENT");
    if (!same) return 1;
  }
  return 0;
}
