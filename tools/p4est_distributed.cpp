// bccmis-p4est-distributed: the distributed run of issue 10.
//
//   mpirun -np 2 --allow-run-as-root --oversubscribe bccmis-p4est-distributed
//
// Every rank builds the same brick forest, refines it (recursively, to level
// L) around a few target points, partitions it, and balances it with
// p4est_balance, first across faces (P4EST_CONNECT_FACE), then in a second
// forest across faces and corners (P4EST_CONNECT_FULL). Rank 0 gathers the
// leaves, imports them into a bccmis lattice (import_quadrants: builds the
// graph from the leaves and runs the checker) and compares the leaf set with
// the one bccmis reaches by refine_balanced on the same targets (edge
// balance; corner balance for the second forest). Exit status 0 when every
// check passed, 1 otherwise; a run on one rank is allowed but says so.
#include <p4est_extended.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "bccmis/apps/balance.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/p4est/bridge.h"

namespace {

using namespace bccmis;

struct Targets {
  const p4est_bridge::Brick* brick;
  std::vector<Point> points;  // strictly inside level-L cells (odd coordinates)
};

// Refine a quadrant that contains a target point, down to level L.
int refine_at_targets(p4est_t* forest, p4est_topidx_t tree, p4est_quadrant_t* q) {
  const auto* t = static_cast<const Targets*>(forest->user_pointer);
  const p4est_bridge::Leaf leaf = t->brick->to_leaf({tree, q->x, q->y, q->level});
  const std::int64_t h = cell_side(t->brick->size(), leaf.level) / 2;
  for (const Point& p : t->points)
    if (p.x > leaf.center.x - h && p.x < leaf.center.x + h && p.y > leaf.center.y - h && p.y < leaf.center.y + h)
      return 1;
  return 0;
}

// bccmis: refine the leaf containing each point until it has level L.
Graph reference(const LatticeSize& size, const std::vector<Point>& points, Balance b) {
  Graph g = make_lattice(size);
  for (const Point& p : points)
    for (int l = 0; l < size.L; ++l) {
      const std::int64_t s = cell_side(size, l);
      const Point c{(p.x / s) * s + s / 2, (p.y / s) * s + s / 2};
      if (g.is_center(c) && !refine_balanced(g, c, b).applied()) throw std::logic_error("refine_balanced refused");
    }
  return g;
}

bool run(const p4est_bridge::Brick& brick, const std::vector<Point>& points, p4est_connect_type_t connect, int rank,
         int ranks) {
  Targets targets{&brick, points};
  p4est_bridge::ForestPtr forest(p4est_new_ext(sc_MPI_COMM_WORLD, brick.connectivity(), 0, 0, 1, 0, nullptr, &targets));
  p4est_refine_ext(forest.get(), 1, brick.size().L, refine_at_targets, nullptr, nullptr);
  p4est_partition(forest.get(), 0, nullptr);
  p4est_balance(forest.get(), connect, nullptr);
  p4est_partition(forest.get(), 0, nullptr);
  const char* mode = connect == P4EST_CONNECT_FACE ? "face" : "full";
  const long local = static_cast<long>(forest->local_num_quadrants);
  std::vector<long> counts(static_cast<std::size_t>(ranks));
  MPI_Gather(&local, 1, MPI_LONG, counts.data(), 1, MPI_LONG, 0, sc_MPI_COMM_WORLD);
  const std::vector<p4est_bridge::Quadrant> all = p4est_bridge::gather_quadrants(forest.get(), 0);
  if (rank != 0) return true;

  bool ok = true;
  std::printf("%s balance: %lld leaves over %d ranks:", mode, static_cast<long long>(forest->global_num_quadrants),
              ranks);
  for (const long c : counts) {
    std::printf(" %ld", c);
    if (ranks > 1 && c == 0) ok = false;
  }
  std::printf("%s\n", ok ? "" : "  (a rank holds no leaf: not distributed)");
  try {
    const Graph g = p4est_bridge::import_quadrants(brick, all);
    std::printf("  imported and checked: %zu cells, %zu nodes\n", g.C.size(), g.N.size());
    const Balance b = connect == P4EST_CONNECT_FACE ? Balance::Edge : Balance::Corner;
    if (b == Balance::Corner)
      if (const auto pair = find_corner_imbalance(g)) {
        std::printf("  FAIL: p4est's full balance left a corner imbalance\n");
        ok = false;
      }
    const Graph expected = reference(brick.size(), points, b);
    if (p4est_bridge::leaves(g) != p4est_bridge::leaves(expected)) {
      std::printf("  FAIL: leaf set differs from bccmis refine_balanced (%s): %zu vs %zu leaves\n",
                  std::string(name(b)).c_str(), g.C.size(), expected.C.size());
      ok = false;
    } else {
      std::printf("  same leaf set as bccmis refine_balanced (%s)\n", std::string(name(b)).c_str());
    }
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
  const LatticeSize size{5, 3, 7};
  const p4est_bridge::Brick brick(size);
  // Points strictly inside level-L cells (odd coordinates): one per region of
  // the brick, so refinement crosses tree boundaries.
  const std::int64_t S = level0_side(size);
  const std::vector<Point> points{{S + 1, S - 1}, {3 * S - 1, 2 * S + 1}, {4 * S + 37, S / 2 + 5}, {9, 3 * S - 3}};
  bool ok = run(brick, points, P4EST_CONNECT_FACE, rank, ranks);
  ok = run(brick, points, P4EST_CONNECT_FULL, rank, ranks) && ok;
  if (expected_ranks != 0 && ranks != expected_ranks) {
    if (rank == 0) std::printf("FAIL: expected %d ranks, running on %d\n", expected_ranks, ranks);
    ok = false;
  }
  int status = ok ? 0 : 1;
  MPI_Bcast(&status, 1, MPI_INT, 0, sc_MPI_COMM_WORLD);
  if (rank == 0) {
    if (ranks < 2) std::printf("note: ran on 1 rank; run under mpirun -np 2 for the distributed check\n");
    std::printf("%s\n", status == 0 ? "OK" : "FAILED");
  }
  return status;
}
