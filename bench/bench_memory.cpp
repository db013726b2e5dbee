// Memory benchmarks (issue 9): bytes per cell of the reference Graph, the
// fast Lattice and a CGAL Surface_mesh half-edge mesh of the same
// triangulation (each cell a fan around its center: the graph's node-center
// edges plus the hull edges of eq. (1)). The paper (§1): "only one third of
// the edges and no faces need to be stored".
//
// Bytes are counted two ways while the structure is alive:
//   bytes_per_cell       what operator new handed out (malloc_usable_size of
//                        every live block: the global operator new of this
//                        executable is replaced to count it,
//                        tests/testing/counting_allocator.h)
//   heap_bytes_per_cell  glibc's in-use heap (mallinfo2: uordblks + hblkhd), which
//                        adds the allocator's per-block headers: what the
//                        process actually pays for many small std::set nodes
// Each is the growth over the state before the structure was built.
//
// States (N = cells):
//   uniform:N   the initial W x W lattice, W^2 ~ N (every cell level 0)
//   adaptive:N  grown from N/4 level-0 cells by random refinements to N cells
//               (bench/workloads.h make_mix): levels 0..8, junctions everywhere.
// Implementations:
//   reference        bccmis::Graph after the same operations (std::set / std::map)
//   fast             bccmis::fast::Lattice after the same operations (pools as grown)
//   fast_shrunk      the same after shrink_to_fit()
//   surface_mesh3        CGAL::Surface_mesh<Epick::Point_3> (z = 0), reserved exactly
//   surface_mesh3_grown  the same built without reserve (arrays as grown by add_face)
//   surface_mesh2        CGAL::Surface_mesh<Epick::Point_2>, reserved exactly
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench_main.h"
#include "halfedge_mesh.h"
#include "testing/counting_allocator.h"
#include "workloads.h"

namespace bccmis::bench {
namespace {

bool g_smoke = false;

std::size_t live_bytes() { return testing::alloc::live_bytes.load(); }
std::size_t heap_bytes() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;  // small blocks in the arenas + large blocks mmapped on their own
}

/// Bytes held by what `build` returns, while it is alive.
struct Measured {
  std::size_t bytes = 0, heap = 0;
};

// ---- States -------------------------------------------------------------------------------

struct StateSpec {
  LatticeSize size;
  std::vector<Point> refines;  // applied to make_lattice(size), in order
};

const StateSpec& state_spec(bool adaptive, std::int64_t cells) {
  static std::map<std::pair<bool, std::int64_t>, std::unique_ptr<StateSpec>> cache;
  auto& s = cache[{adaptive, cells}];
  if (!s) {
    s = std::make_unique<StateSpec>();
    if (adaptive) {
      Mix mix = make_mix(cells, 0, 11);
      s->size = mix.size;
      s->refines = std::move(mix.warmup);
    } else {
      s->size = square_lattice(cells, 4);
    }
  }
  return *s;
}

/// The triangulation of a lattice: every cell a fan of triangles around its
/// center over its boundary nodes in counter-clockwise order.
Triangulation triangulation_of(const fast::Lattice& g) {
  Triangulation t;
  const auto& centers = g.center_pool();
  const auto& nodes = g.node_pool();
  constexpr auto kNone = fast::Lattice::kNone;
  std::vector<std::uint32_t> center_id(centers.size(), kNone), node_id(nodes.size(), kNone);
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (nodes[n].live()) {
      node_id[n] = static_cast<std::uint32_t>(t.points.size());
      const Point p = g.node_position(static_cast<fast::Lattice::Index>(n));
      t.points.push_back({static_cast<double>(p.x), static_cast<double>(p.y)});
    }
  for (std::size_t c = 0; c < centers.size(); ++c) {
    if (!centers[c].live()) continue;
    center_id[c] = static_cast<std::uint32_t>(t.points.size());
    const Point p = centers[c].position();
    t.points.push_back({static_cast<double>(p.x), static_cast<double>(p.y)});
    // Counter-clockwise from the south-west corner: SW, S, SE, E, NE, N, NW, W.
    const fast::Lattice::Index ring[8] = {centers[c].corner[0], centers[c].mid[0],    centers[c].corner[1],
                                          centers[c].mid[1],    centers[c].corner[3], centers[c].mid[2],
                                          centers[c].corner[2], centers[c].mid[3]};
    std::vector<std::uint32_t> b;
    for (const auto n : ring)
      if (n != kNone) b.push_back(node_id[n]);
    for (std::size_t k = 0; k < b.size(); ++k) t.triangles.push_back({center_id[c], b[k], b[(k + 1) % b.size()]});
  }
  return t;
}

std::size_t stored_edges(const fast::Lattice& g) {
  std::size_t e = 0;
  for (const auto& c : g.center_pool())
    if (c.live())
      for (int s = 0; s < 4; ++s) e += 1 + (c.mid[s] != fast::Lattice::kNone);
  return e;
}

void report(benchmark::State& st, const Measured& m, std::size_t cells) {
  st.counters["cells"] = static_cast<double>(cells);
  st.counters["bytes_per_cell"] = static_cast<double>(m.bytes) / static_cast<double>(cells);
  st.counters["heap_bytes_per_cell"] = static_cast<double>(m.heap) / static_cast<double>(cells);
}

// ---- Benchmarks ------------------------------------------------------------------------------

void BM_Reference(benchmark::State& st) {
  const StateSpec& spec = state_spec(st.range(0) != 0, st.range(1));
  for (auto _ : st) {
    const std::size_t b0 = live_bytes(), h0 = heap_bytes();
    auto g = std::make_unique<Graph>(make_lattice(spec.size));
    for (const Point& c : spec.refines) bccmis::refine(*g, c);
    Measured m{live_bytes() - b0, heap_bytes() - h0};
    report(st, m, g->C.size());
    st.PauseTiming();
    g.reset();
    malloc_trim(0);  // consolidate the freed std::set nodes now, not in the next benchmark's first malloc
    st.ResumeTiming();
  }
}

void BM_Fast(benchmark::State& st, bool shrink) {
  const StateSpec& spec = state_spec(st.range(0) != 0, st.range(1));
  for (auto _ : st) {
    const std::size_t b0 = live_bytes(), h0 = heap_bytes();
    auto g = std::make_unique<fast::Lattice>(spec.size);
    for (const Point& c : spec.refines) g->refine(c);
    if (shrink) g->shrink_to_fit();
    Measured m{live_bytes() - b0, heap_bytes() - h0};
    report(st, m, g->cell_count());
    st.counters["self_reported_bytes_per_cell"] =
        static_cast<double>(g->memory_bytes()) / static_cast<double>(g->cell_count());
    st.counters["stored_edges_per_cell"] = static_cast<double>(stored_edges(*g)) / static_cast<double>(g->cell_count());
    st.PauseTiming();
    g.reset();
    st.ResumeTiming();
  }
}

void BM_SurfaceMesh(benchmark::State& st, bool point3, bool reserve) {
  const StateSpec& spec = state_spec(st.range(0) != 0, st.range(1));
  fast::Lattice g(spec.size);
  for (const Point& c : spec.refines) g.refine(c);
  const Triangulation t = triangulation_of(g);
  for (auto _ : st) {
    const std::size_t h0 = heap_bytes();
    std::size_t heap = 0;
    const HalfedgeMeshStats s = surface_mesh_of(t, point3, reserve, [&] {
      heap = heap_bytes() - h0;
      return live_bytes();
    });
    if (!s.ok) st.SkipWithError("a face could not be added to the Surface_mesh");
    report(st, Measured{s.bytes, heap}, g.cell_count());
    st.counters["edges_per_cell"] = static_cast<double>(s.edges) / static_cast<double>(g.cell_count());
    st.counters["faces_per_cell"] = static_cast<double>(s.faces) / static_cast<double>(g.cell_count());
    st.counters["graph_edges_over_mesh_edges"] = static_cast<double>(stored_edges(g)) / static_cast<double>(s.edges);
  }
}

void register_all() {
  const std::vector<std::int64_t> sizes =
      g_smoke ? std::vector<std::int64_t>{1000} : std::vector<std::int64_t>{1000, 10'000, 100'000, 1'000'000};
  auto add = [&](const char* name, auto fn) {
    auto* b = benchmark::RegisterBenchmark(name, fn);
    b->ArgNames({"adaptive", "cells"})->Iterations(1)->Unit(benchmark::kMillisecond);
    for (const int adaptive : {0, 1})
      for (const std::int64_t n : sizes) b->Args({adaptive, n});
  };
  add("Memory/reference", BM_Reference);
  add("Memory/fast", [](benchmark::State& st) { BM_Fast(st, false); });
  add("Memory/fast_shrunk", [](benchmark::State& st) { BM_Fast(st, true); });
  add("Memory/surface_mesh3", [](benchmark::State& st) { BM_SurfaceMesh(st, true, true); });
  add("Memory/surface_mesh3_grown", [](benchmark::State& st) { BM_SurfaceMesh(st, true, false); });
  add("Memory/surface_mesh2", [](benchmark::State& st) { BM_SurfaceMesh(st, false, true); });
}

}  // namespace
}  // namespace bccmis::bench

int main(int argc, char** argv) {
  using namespace bccmis::bench;
  take_flags(argc, argv, [](std::string_view a) { return a == "--bccmis_smoke" && (g_smoke = true); });
  register_all();
  return run_benchmarks(argc, argv);
}
