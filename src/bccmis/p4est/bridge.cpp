#include "bccmis/p4est/bridge.h"

#include <p4est_extended.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "bccmis/invariants/invariants.h"
#include "bccmis/ops.h"
#include "bccmis/p4est/detail/gather.h"

namespace bccmis::p4est_bridge {

namespace {

std::string at(const Point& p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

std::string describe(const Leaf& leaf) {
  return "the level-" + std::to_string(leaf.level) + " cell centered at " + at(leaf.center);
}

std::string describe(const Quadrant& q) {
  return "quadrant (tree " + std::to_string(q.tree) + ", x " + std::to_string(q.x) + ", y " + std::to_string(q.y) +
         ", level " + std::to_string(q.level) + ")";
}

// The level-k ancestor of a leaf (k <= leaf.level): the cell of side s_k
// containing the leaf's center.
Leaf ancestor(const LatticeSize& size, const Leaf& leaf, int k) {
  const std::int64_t s = cell_side(size, k);
  return {{(leaf.center.x / s) * s + s / 2, (leaf.center.y / s) * s + s / 2}, k};
}

// Coarsest first, then by position: the order in which import refines.
bool level_first(const Leaf& a, const Leaf& b) { return a.level != b.level ? a.level < b.level : a.center < b.center; }

int g_sessions = 0;
bool g_owns_mpi = false;

}  // namespace

// ---- Session ------------------------------------------------------------------------------

Session::Session(int* argc, char*** argv) {
  if (g_sessions++ > 0) return;
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (finalized) {
      --g_sessions;
      throw std::logic_error("bccmis::p4est_bridge::Session: MPI was finalized already (one Session span per process)");
    }
    // Without mpirun, OpenMPI starts a singleton (about 0.4 s).
    MPI_Init(argc, argv);
    g_owns_mpi = true;
  }
  sc_init(sc_MPI_COMM_WORLD, 0, 0, nullptr, SC_LP_ERROR);
  p4est_init(nullptr, SC_LP_ERROR);
}

Session::~Session() {
  if (--g_sessions > 0) return;
  sc_finalize();
  if (g_owns_mpi) MPI_Finalize();
  g_owns_mpi = false;
}

void ConnectivityDeleter::operator()(p4est_connectivity_t* c) const noexcept { p4est_connectivity_destroy(c); }
void ForestDeleter::operator()(p4est_t* p) const noexcept { p4est_destroy(p); }

// ---- Brick ---------------------------------------------------------------------------------

Brick::Brick(const LatticeSize& size) : size_(size) {
  validate_lattice_size(size);
  if (size.L > P4EST_QMAXLEVEL)
    throw std::invalid_argument("bccmis::p4est_bridge: L = " + std::to_string(size.L) +
                                " exceeds P4EST_QMAXLEVEL = " + std::to_string(P4EST_QMAXLEVEL));
  if (size.W > std::numeric_limits<std::int32_t>::max() / size.H)
    throw std::invalid_argument("bccmis::p4est_bridge: W x H = " + std::to_string(size.W) + " x " +
                                std::to_string(size.H) + " trees exceed p4est's tree index");
  shift_ = P4EST_QMAXLEVEL - size.L;
  conn_.reset(p4est_connectivity_new_brick(static_cast<int>(size.W), static_cast<int>(size.H), 0, 0));
  const auto trees = static_cast<std::size_t>(size.W * size.H);
  if (static_cast<std::size_t>(conn_->num_trees) != trees)
    throw std::logic_error("bccmis::p4est_bridge: the brick has " + std::to_string(conn_->num_trees) +
                           " trees, expected " + std::to_string(trees));
  // The brick's tree numbering, read from its vertex coordinates: tree t's
  // corners are tree_to_vertex[4t + k], k = 0..3 in p4est's z-order
  // (x fastest), at (i, j), (i+1, j), (i, j+1), (i+1, j+1).
  tree_of_cell_.assign(trees, -1);
  cell_of_tree_.assign(trees, -1);
  for (std::size_t t = 0; t < trees; ++t) {
    std::int64_t corner[4][2];
    for (int k = 0; k < 4; ++k) {
      const p4est_topidx_t v = conn_->tree_to_vertex[4 * t + static_cast<std::size_t>(k)];
      corner[k][0] = std::llround(conn_->vertices[3 * v]);
      corner[k][1] = std::llround(conn_->vertices[3 * v + 1]);
    }
    const std::int64_t i = corner[0][0], j = corner[0][1];
    const bool z_order = corner[1][0] == i + 1 && corner[1][1] == j && corner[2][0] == i && corner[2][1] == j + 1 &&
                         corner[3][0] == i + 1 && corner[3][1] == j + 1;
    if (!z_order || i < 0 || j < 0 || i >= size.W || j >= size.H ||
        tree_of_cell_[static_cast<std::size_t>(j * size.W + i)] != -1)
      throw std::logic_error("bccmis::p4est_bridge: brick tree " + std::to_string(t) +
                             " is not a unit square of the W x H grid in z-order corners");
    tree_of_cell_[static_cast<std::size_t>(j * size.W + i)] = static_cast<std::int32_t>(t);
    cell_of_tree_[t] = j * size.W + i;
  }
}

std::int32_t Brick::tree(std::int64_t i, std::int64_t j) const {
  return tree_of_cell_.at(static_cast<std::size_t>(j * size_.W + i));
}

Quadrant Brick::to_quadrant(const Leaf& leaf) const {
  const std::int64_t S = level0_side(size_);
  const std::int64_t half = cell_side(size_, leaf.level) / 2;
  const std::int64_t x0 = leaf.center.x - half, y0 = leaf.center.y - half;  // lower-left corner
  const std::int64_t i = x0 / S, j = y0 / S;
  return {tree(i, j), static_cast<std::int32_t>((x0 - i * S) << shift_),
          static_cast<std::int32_t>((y0 - j * S) << shift_), leaf.level};
}

Leaf Brick::to_leaf(const Quadrant& q) const {
  if (q.tree < 0 || static_cast<std::size_t>(q.tree) >= cell_of_tree_.size())
    throw ImportError("bccmis::p4est_bridge: " + describe(q) + ": no such tree in the " + std::to_string(size_.W) +
                      " x " + std::to_string(size_.H) + " brick");
  if (q.level < 0 || q.level > size_.L)
    throw ImportError("bccmis::p4est_bridge: " + describe(q) + ": level " + std::to_string(q.level) +
                      (q.level < 0 ? " is negative" : " is deeper than the lattice's L = " + std::to_string(size_.L)));
  const std::int64_t len = std::int64_t{1} << (P4EST_MAXLEVEL - q.level);
  if (q.x < 0 || q.y < 0 || q.x >= P4EST_ROOT_LEN || q.y >= P4EST_ROOT_LEN || q.x % len != 0 || q.y % len != 0)
    throw ImportError("bccmis::p4est_bridge: " + describe(q) + ": not a level-" + std::to_string(q.level) +
                      " quadrant inside its tree");
  const std::int64_t S = level0_side(size_);
  const std::int64_t cell = cell_of_tree_[static_cast<std::size_t>(q.tree)];
  const std::int64_t i = cell % size_.W, j = cell / size_.W;
  const std::int64_t half = cell_side(size_, q.level) / 2;
  return {{i * S + (std::int64_t{q.x} >> shift_) + half, j * S + (std::int64_t{q.y} >> shift_) + half}, q.level};
}

// ---- Export ----------------------------------------------------------------------------------

std::vector<Leaf> leaves(const Graph& g) {
  std::vector<Leaf> out;
  out.reserve(g.C.size());
  for (const auto& [c, l] : g.level) out.push_back({c, l});
  return out;  // std::map order: sorted by center
}

namespace {

struct RefineContext {
  const Brick* brick;
  std::vector<Leaf> sorted;  // by operator<
};

int refine_to_leaves(p4est_t* forest, p4est_topidx_t tree, p4est_quadrant_t* q) {
  const auto* ctx = static_cast<const RefineContext*>(forest->user_pointer);
  try {
    const Leaf leaf = ctx->brick->to_leaf({tree, q->x, q->y, q->level});
    return std::binary_search(ctx->sorted.begin(), ctx->sorted.end(), leaf) ? 0 : 1;
  } catch (...) {
    return 0;  // cannot happen below maxlevel L; make_forest then reports the mismatch
  }
}

}  // namespace

ForestPtr make_forest(const Brick& brick, std::span<const Leaf> leaves, sc_MPI_Comm comm) {
  RefineContext ctx{&brick, std::vector<Leaf>(leaves.begin(), leaves.end())};
  std::sort(ctx.sorted.begin(), ctx.sorted.end());
  ctx.sorted.erase(std::unique(ctx.sorted.begin(), ctx.sorted.end()), ctx.sorted.end());
  ForestPtr forest(p4est_new_ext(comm, brick.connectivity(), 0, 0, 1, 0, nullptr, &ctx));
  p4est_refine_ext(forest.get(), 1, brick.size().L, refine_to_leaves, nullptr, nullptr);
  forest->user_pointer = nullptr;
  // Every forest leaf is a requested leaf, and there are as many: the leaves
  // tile the lattice. Decided collectively, so every rank throws or none.
  long local_bad = 0;
  for (const Quadrant& q : local_quadrants(forest.get()))
    if (!std::binary_search(ctx.sorted.begin(), ctx.sorted.end(), brick.to_leaf(q))) ++local_bad;
  long bad = 0;
  MPI_Allreduce(&local_bad, &bad, 1, MPI_LONG, MPI_SUM, comm);
  if (bad != 0 || static_cast<std::size_t>(forest->global_num_quadrants) != ctx.sorted.size())
    throw ImportError("bccmis::p4est_bridge: the " + std::to_string(ctx.sorted.size()) +
                      " leaves do not tile the lattice (the forest refined to them has " +
                      std::to_string(forest->global_num_quadrants) + " leaves, " + std::to_string(bad) +
                      " of them not requested)");
  return forest;
}

ForestPtr export_forest(const Brick& brick, const Graph& g, sc_MPI_Comm comm) {
  if (!(g.size == brick.size()))
    throw std::invalid_argument("bccmis::p4est_bridge: the graph and the brick differ in size");
  const std::vector<Leaf> all = leaves(g);
  return make_forest(brick, all, comm);
}

std::vector<Quadrant> local_quadrants(const p4est_t* forest) {
  std::vector<Quadrant> out;
  out.reserve(static_cast<std::size_t>(forest->local_num_quadrants));
  if (forest->first_local_tree < 0) return out;  // this rank holds no quadrant
  for (p4est_topidx_t t = forest->first_local_tree; t <= forest->last_local_tree; ++t) {
    const p4est_tree_t* tree = p4est_tree_array_index(forest->trees, t);
    const sc_array_t* qs = &tree->quadrants;
    for (std::size_t k = 0; k < qs->elem_count; ++k) {
      const p4est_quadrant_t* q = p4est_quadrant_array_index(const_cast<sc_array_t*>(qs), k);
      out.push_back({t, q->x, q->y, q->level});
    }
  }
  return out;
}

std::vector<Quadrant> gather_quadrants(const p4est_t* forest, int root) {
  static_assert(sizeof(Quadrant) == 4 * sizeof(std::int32_t));
  return detail::gather(local_quadrants(forest), forest->mpicomm, root);
}

// ---- Import ----------------------------------------------------------------------------------

Graph import_leaves(const LatticeSize& size, std::span<const Leaf> input) {
  validate_lattice_size(size);
  std::vector<Leaf> sorted(input.begin(), input.end());
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 1; k < sorted.size(); ++k)
    if (sorted[k] == sorted[k - 1])
      throw ImportError("bccmis::p4est_bridge: " + describe(sorted[k]) + " is listed twice");
  // Every proper ancestor of a leaf is a refined cell of the lattice.
  std::vector<Leaf> refined;
  const std::int64_t width = size.W * level0_side(size), height = size.H * level0_side(size);
  for (const Leaf& leaf : sorted) {
    if (leaf.level < 0 || leaf.level > size.L)
      throw ImportError("bccmis::p4est_bridge: " + describe(leaf) + ": level outside 0.." + std::to_string(size.L));
    const std::int64_t s = cell_side(size, leaf.level);
    const Point& c = leaf.center;
    if (c.x <= 0 || c.y <= 0 || c.x >= width || c.y >= height || (c.x - s / 2) % s != 0 || (c.y - s / 2) % s != 0)
      throw ImportError("bccmis::p4est_bridge: " + describe(leaf) + " is not a cell of the lattice");
    for (int k = 0; k < leaf.level; ++k) refined.push_back(ancestor(size, leaf, k));
  }
  std::sort(refined.begin(), refined.end());
  refined.erase(std::unique(refined.begin(), refined.end()), refined.end());
  for (const Leaf& leaf : sorted)
    if (std::binary_search(refined.begin(), refined.end(), leaf))
      throw ImportError("bccmis::p4est_bridge: leaves overlap: " + describe(leaf) +
                        " is a leaf and contains other leaves");
  // Refine coarsest first. Before level k, every refined cell coarser than k
  // is refined, so a cell coarser than k is a leaf of the input. refine(c)
  // (eq. 3, erratum E4) refuses exactly when an edge-neighbor of c is such
  // a leaf, i.e. when a leaf of level >= k+1 inside c and a leaf of level
  // < k across c's side differ by 2 or more: the input is not face balanced.
  std::sort(refined.begin(), refined.end(), level_first);
  Graph g = make_lattice(size);
  for (const Leaf& c : refined) {
    const RefineResult r = refine(g, c.center);
    if (r.refused == RefineRefusal::CoarserNeighbor)
      throw ImportError("bccmis::p4est_bridge: the forest is not face balanced (2:1 across faces): " + describe(c) +
                        " holds leaves of level " + std::to_string(c.level + 1) +
                        " or finer, but an edge-neighbor is a leaf coarser than level " + std::to_string(c.level));
    if (!r.applied())
      throw ImportError("bccmis::p4est_bridge: " + describe(c) +
                        " cannot be refined: " + std::string(code(*r.refused)));
  }
  if (g.C.size() != sorted.size()) {
    for (const auto& [c, l] : g.level)
      if (!std::binary_search(sorted.begin(), sorted.end(), Leaf{c, l}))
        throw ImportError("bccmis::p4est_bridge: the leaves do not cover the lattice: nothing covers " +
                          describe(Leaf{c, l}));
  }
  if (const std::optional<Violation> v = find_violation(g))
    throw ImportError("bccmis::p4est_bridge: the imported lattice fails the checker: " + to_string(*v));
  return g;
}

Graph import_quadrants(const Brick& brick, std::span<const Quadrant> quadrants) {
  std::vector<Leaf> input;
  input.reserve(quadrants.size());
  for (const Quadrant& q : quadrants) input.push_back(brick.to_leaf(q));
  return import_leaves(brick.size(), input);
}

Graph import_forest(const Brick& brick, const p4est_t* forest) {
  if (forest->global_num_quadrants != forest->local_num_quadrants)
    throw ImportError("bccmis::p4est_bridge: import_forest needs the whole forest on this rank (" +
                      std::to_string(forest->local_num_quadrants) + " of " +
                      std::to_string(forest->global_num_quadrants) + " quadrants); use gather_quadrants");
  if (forest->connectivity->num_trees != brick.connectivity()->num_trees)
    throw ImportError("bccmis::p4est_bridge: the forest's connectivity is not the brick's");
  const std::vector<Quadrant> qs = local_quadrants(forest);
  return import_quadrants(brick, qs);
}

}  // namespace bccmis::p4est_bridge
