// bccmis-p4est-distributed and bccmis-p8est-distributed: the distributed run
// of issue 10, in 2D with p4est and, compiled with BCCMIS_P4_TO_P8 defined
// (as p4est compiles p8est.c from p4est.c), in 3D with p8est
// (spec/p4est.md "3D").
//
//   mpirun -np 2 --allow-run-as-root --oversubscribe bccmis-p4est-distributed
//   mpirun -np 2 --allow-run-as-root --oversubscribe bccmis-p8est-distributed --expect-ranks 2
//
// Every rank builds the same brick forest, refines it (recursively, to level
// L) around a few target points, partitions it, and balances it with
// p4est_balance / p8est_balance: first with the core's rule (across faces,
// P4EST_CONNECT_FACE; across faces and edges in 3D, P8EST_CONNECT_EDGE),
// then, in a second forest, across corners too (P4EST_CONNECT_FULL,
// P8EST_CONNECT_FULL). Rank 0 gathers the leaves, imports them into a bccmis
// lattice (import_quadrants: builds the graph from the leaves, refuses an
// unbalanced forest, runs the checker) and compares the leaf set with the one
// bccmis reaches by refine_balanced on the same targets (edge balance; corner
// balance for the second forest). Exit status 0 when every check passed, 1
// otherwise; a 2D run on one rank is allowed but says so.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "bccmis/balance.h"
#include "bccmis/d3/lattice.h"
#include "bccmis/p4est/bridge.h"

namespace {

using namespace bccmis;

// The names that differ between the dimensions (bridge.h's traits P4<Dim>);
// everything below is written once.
#ifndef BCCMIS_P4_TO_P8
constexpr int kDim = 2;
#else
constexpr int kDim = 3;
#endif
using P4 = p4est_bridge::P4<kDim>;
using Lattice = P4::Graph;
using Size = P4::LatticeSize;
using Pt = P4::Point;
using Brick = p4est_bridge::BrickOf<kDim>;
using Leaf = p4est_bridge::LeafOf<kDim>;
using Quadrant = p4est_bridge::QuadrantOf<kDim>;
using ForestPtr = p4est_bridge::ForestPtrOf<kDim>;
using forest_t = P4::forest_t;
using quadrant_t = P4::quadrant_t;
using connect_t = P4::connect_type_t;
constexpr connect_t kConnectEdge = P4::kConnectCore;
constexpr connect_t kConnectFull = P4::kConnectFull;

struct Targets {
  const Brick* brick;
  std::vector<Pt> points;  // strictly inside level-L cells (odd coordinates)
};

// Whether p lies strictly inside the cell of `leaf`, of half side h.
bool holds(const Leaf& leaf, std::int64_t h, const Pt& p) {
  const Pt& c = leaf.center;
  return p.x > c.x - h && p.x < c.x + h && p.y > c.y - h && p.y < c.y + h
#ifdef BCCMIS_P4_TO_P8
         && p.z > c.z - h && p.z < c.z + h
#endif
      ;
}

// Refine a quadrant that contains a target point, down to level L.
int refine_at_targets(forest_t* forest, p4est_topidx_t tree, quadrant_t* q) {
  const auto* t = static_cast<const Targets*>(forest->user_pointer);
#ifndef BCCMIS_P4_TO_P8
  const Leaf leaf = t->brick->to_leaf({tree, q->x, q->y, q->level});
#else
  const Leaf leaf = t->brick->to_leaf({tree, q->x, q->y, q->z, q->level});
#endif
  const std::int64_t h = cell_side(t->brick->size(), leaf.level) / 2;
  for (const Pt& p : t->points)
    if (holds(leaf, h, p)) return 1;
  return 0;
}

// bccmis: refine the leaf containing each point, with the cascade, until it has level L.
Lattice reference(const Size& size, const std::vector<Pt>& points, Balance b) {
  Lattice g(size);
  for (const Pt& p : points)
    for (int l = 0; l < size.L; ++l) {
      const std::int64_t s = cell_side(size, l);
      auto snap = [s](std::int64_t v) { return (v / s) * s + s / 2; };
#ifndef BCCMIS_P4_TO_P8
      const Pt c{snap(p.x), snap(p.y)};
#else
      const Pt c{snap(p.x), snap(p.y), snap(p.z)};
#endif
      if (g.is_center(c) && !refine_balanced(g, c, b).applied()) throw std::logic_error("refine_balanced refused");
    }
  return g;
}

bool run(const Brick& brick, const std::vector<Pt>& points, connect_t connect, int rank, int ranks) {
  Targets targets{&brick, points};
  ForestPtr forest(P4::new_ext(sc_MPI_COMM_WORLD, brick.connectivity(), 0, 0, 1, 0, nullptr, &targets));
  P4::refine_ext(forest.get(), 1, brick.size().L, refine_at_targets, nullptr, nullptr);
  P4::partition(forest.get(), 0, nullptr);
  P4::balance(forest.get(), connect, nullptr);
  P4::partition(forest.get(), 0, nullptr);
  const Balance b = connect == kConnectEdge ? Balance::Edge : Balance::Corner;
  const long local = static_cast<long>(forest->local_num_quadrants);
  std::vector<long> counts(static_cast<std::size_t>(ranks));
  MPI_Gather(&local, 1, MPI_LONG, counts.data(), 1, MPI_LONG, 0, sc_MPI_COMM_WORLD);
  const std::vector<Quadrant> all = p4est_bridge::gather_quadrants(forest.get(), 0);
  if (rank != 0) return true;

  bool ok = true;
#ifndef BCCMIS_P4_TO_P8
  std::printf("%s balance: %lld leaves over %d ranks:", b == Balance::Edge ? "face" : "full",
              static_cast<long long>(forest->global_num_quadrants), ranks);
#else
  std::printf("p8est %s balance: %lld octants over %d ranks:", b == Balance::Edge ? "edge" : "full",
              static_cast<long long>(forest->global_num_quadrants), ranks);
#endif
  for (const long c : counts) {
    std::printf(" %ld", c);
    if (ranks > 1 && c == 0) ok = false;
  }
#ifndef BCCMIS_P4_TO_P8
  std::printf("%s\n", ok ? "" : "  (a rank holds no leaf: not distributed)");
#else
  std::printf("%s\n", ok ? "" : "  FAIL: a rank holds no octant, not distributed");
#endif
  try {
    const Lattice g = p4est_bridge::import_quadrants(brick, all);
    std::printf("  imported and checked: %zu cells, %zu nodes\n", g.C.size(), g.N.size());
#ifndef BCCMIS_P4_TO_P8
    const char* const library = "p4est";
#else
    const char* const library = "p8est";
#endif
    if (b == Balance::Corner && find_corner_imbalance(g)) {
      std::printf("  FAIL: %s's full balance left a corner imbalance\n", library);
      ok = false;
    }
    const Lattice expected = reference(brick.size(), points, b);
    const bool same = p4est_bridge::leaves(g) == p4est_bridge::leaves(expected);
#ifndef BCCMIS_P4_TO_P8
    if (same)
      std::printf("  same leaf set as bccmis refine_balanced (%s)\n", std::string(name(b)).c_str());
    else
      std::printf("  FAIL: leaf set differs from bccmis refine_balanced (%s): %zu vs %zu leaves\n",
                  std::string(name(b)).c_str(), g.C.size(), expected.C.size());
#else
    std::printf("  %s bccmis refine_balanced (%s): %zu vs %zu leaves\n",
                same ? "same leaf set as" : "FAIL: differs from", std::string(name(b)).c_str(), g.C.size(),
                expected.C.size());
#endif
    ok = ok && same;
  } catch (const std::exception& e) {
    std::printf("  FAIL: %s\n", e.what());
    ok = false;
  }
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  p4est_bridge::Session session(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(sc_MPI_COMM_WORLD, &rank);
  MPI_Comm_size(sc_MPI_COMM_WORLD, &ranks);
  int expected_ranks = 0;  // --expect-ranks N: fail unless run on N ranks
  for (int k = 1; k + 1 < argc; ++k)
    if (std::string(argv[k]) == "--expect-ranks") expected_ranks = std::atoi(argv[k + 1]);
#ifndef BCCMIS_P4_TO_P8
  const Size size{5, 3, 7};
  // Points strictly inside level-L cells (odd coordinates): one per region of
  // the brick, so refinement crosses tree boundaries.
  const std::int64_t S = level0_side(size);
  const std::vector<Pt> points{{S + 1, S - 1}, {3 * S - 1, 2 * S + 1}, {4 * S + 37, S / 2 + 5}, {9, 3 * S - 3}};
#else
  const Size size{3, 2, 2, 3};
  // Odd coordinates, near tree boundaries, so the balance crosses trees.
  const std::int64_t S = level0_side(size);
  const std::vector<Pt> points{{S + 1, S - 1, S + 1}, {3 * S - 1, 2 * S - 3, 5}, {2 * S - 1, 7, 2 * S - 1}};
#endif
  const Brick brick(size);
  bool ok = run(brick, points, kConnectEdge, rank, ranks);
  ok = run(brick, points, kConnectFull, rank, ranks) && ok;
  if (expected_ranks != 0 && ranks != expected_ranks) {
    if (rank == 0) std::printf("FAIL: expected %d ranks, running on %d\n", expected_ranks, ranks);
    ok = false;
  }
  int status = ok ? 0 : 1;
  MPI_Bcast(&status, 1, MPI_INT, 0, sc_MPI_COMM_WORLD);
  if (rank == 0) {
#ifndef BCCMIS_P4_TO_P8
    if (ranks < 2) std::printf("note: ran on 1 rank; run under mpirun -np 2 for the distributed check\n");
#endif
    std::printf("%s\n", status == 0 ? "OK" : "FAILED");
  }
  return status;
}
