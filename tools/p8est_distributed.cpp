// bccmis-p8est-distributed: the 3D distributed run (spec/p4est.md "3D").
//
//   mpirun -np 2 --allow-run-as-root --oversubscribe bccmis-p8est-distributed --expect-ranks 2
//
// Every rank builds the same W x H x D brick forest, refines it (recursively,
// to level L) around a few target points, partitions it, and balances it
// with p8est_balance: across faces and edges (P8EST_CONNECT_EDGE), then, in a
// second forest, across corners too (P8EST_CONNECT_FULL). Rank 0 gathers the
// octants, imports them into a 3D bccmis lattice (import_quadrants: builds
// the graph from the leaves, refuses an unbalanced forest, runs the 3D
// checker) and compares the leaf set with the one the 3D refine_balanced
// reaches on the same targets (edge mode; corner mode for the second forest).
// Exit status 0 when every check passed, 1 otherwise; prints FAIL on a failure.
#include <p8est_extended.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "bccmis/apps/balance3.h"
#include "bccmis/p4est/bridge3.h"

namespace {

using namespace bccmis;
using d3::Point3;

struct Points3 {
  const p4est_bridge::Brick3* brick;
  std::vector<Point3> points;  // strictly inside level-L cubes (odd coordinates)
};

bool holds(const p4est_bridge::Leaf3& leaf, std::int64_t h, const Point3& p) {
  const Point3& c = leaf.center;
  return p.x > c.x - h && p.x < c.x + h && p.y > c.y - h && p.y < c.y + h && p.z > c.z - h && p.z < c.z + h;
}

int split_at_points(p8est_t* forest, p4est_topidx_t tree, p8est_quadrant_t* q) {
  const auto* t = static_cast<const Points3*>(forest->user_pointer);
  const p4est_bridge::Leaf3 leaf = t->brick->to_leaf({tree, q->x, q->y, q->z, q->level});
  const std::int64_t h = d3::cell_side(t->brick->size(), leaf.level) / 2;
  for (const Point3& p : t->points)
    if (holds(leaf, h, p)) return 1;
  return 0;
}

// bccmis: the cube containing each point, refined with the cascade down to level L.
d3::Graph3 reference(const d3::LatticeSize3& size, const std::vector<Point3>& points, Balance b) {
  d3::Graph3 g(size);
  for (const Point3& p : points)
    for (int l = 0; l < size.L; ++l) {
      const std::int64_t s = d3::cell_side(size, l);
      const Point3 c{(p.x / s) * s + s / 2, (p.y / s) * s + s / 2, (p.z / s) * s + s / 2};
      if (g.is_center(c) && !d3::refine_balanced(g, c, b).applied()) throw std::logic_error("refine_balanced refused");
    }
  return g;
}

bool balance_and_compare(const p4est_bridge::Brick3& brick, const std::vector<Point3>& points,
                         p8est_connect_type_t connect, int rank, int ranks) {
  Points3 targets{&brick, points};
  p4est_bridge::Forest3Ptr forest(
      p8est_new_ext(sc_MPI_COMM_WORLD, brick.connectivity(), 0, 0, 1, 0, nullptr, &targets));
  p8est_refine_ext(forest.get(), 1, brick.size().L, split_at_points, nullptr, nullptr);
  p8est_partition(forest.get(), 0, nullptr);
  p8est_balance(forest.get(), connect, nullptr);
  p8est_partition(forest.get(), 0, nullptr);
  const Balance mode = connect == P8EST_CONNECT_EDGE ? Balance::Edge : Balance::Corner;
  const long mine = static_cast<long>(forest->local_num_quadrants);
  std::vector<long> per_rank(static_cast<std::size_t>(ranks));
  MPI_Gather(&mine, 1, MPI_LONG, per_rank.data(), 1, MPI_LONG, 0, sc_MPI_COMM_WORLD);
  const std::vector<p4est_bridge::Quadrant3> all = p4est_bridge::gather_quadrants(forest.get(), 0);
  if (rank != 0) return true;

  bool ok = true;
  std::printf("p8est %s balance: %lld octants over %d ranks:", connect == P8EST_CONNECT_EDGE ? "edge" : "full",
              static_cast<long long>(forest->global_num_quadrants), ranks);
  for (const long n : per_rank) {
    std::printf(" %ld", n);
    ok = ok && !(ranks > 1 && n == 0);
  }
  std::printf("%s\n", ok ? "" : "  FAIL: a rank holds no octant, not distributed");
  try {
    const d3::Graph3 g = p4est_bridge::import_quadrants(brick, all);
    std::printf("  imported and checked: %zu cells, %zu nodes\n", g.C.size(), g.N.size());
    if (mode == Balance::Corner && d3::find_corner_imbalance(g)) {
      std::printf("  FAIL: p8est's full balance left a corner imbalance\n");
      ok = false;
    }
    const d3::Graph3 expected = reference(brick.size(), points, mode);
    const bool same = p4est_bridge::leaves(g) == p4est_bridge::leaves(expected);
    std::printf("  %s bccmis refine_balanced (%s): %zu vs %zu leaves\n",
                same ? "same leaf set as" : "FAIL: differs from", std::string(name(mode)).c_str(), g.C.size(),
                expected.C.size());
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
  int want_ranks = 0;  // --expect-ranks N: fail unless run on N ranks
  for (int k = 1; k + 1 < argc; ++k)
    if (std::string(argv[k]) == "--expect-ranks") want_ranks = std::atoi(argv[k + 1]);
  const d3::LatticeSize3 size{3, 2, 2, 3};
  const p4est_bridge::Brick3 brick(size);
  // Odd coordinates, near tree boundaries, so the balance crosses trees.
  const std::int64_t S = d3::level0_side(size);
  const std::vector<Point3> points{{S + 1, S - 1, S + 1}, {3 * S - 1, 2 * S - 3, 5}, {2 * S - 1, 7, 2 * S - 1}};
  bool ok = balance_and_compare(brick, points, P8EST_CONNECT_EDGE, rank, ranks);
  ok = balance_and_compare(brick, points, P8EST_CONNECT_FULL, rank, ranks) && ok;
  if (want_ranks != 0 && ranks != want_ranks) {
    if (rank == 0) std::printf("FAIL: expected %d ranks, running on %d\n", want_ranks, ranks);
    ok = false;
  }
  int status = ok ? 0 : 1;
  MPI_Bcast(&status, 1, MPI_INT, 0, sc_MPI_COMM_WORLD);
  if (rank == 0) std::printf("%s\n", status == 0 ? "OK" : "FAILED");
  return status;
}
