// The p4est and p8est bridges, written once over the dimension (bridge.h)
// and instantiated for Dim = 2 (p4est) and Dim = 3 (p8est) at the end.
#include "bccmis/p4est/bridge.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "bccmis/d3/ops.h"
#include "bccmis/invariants/d3/invariants.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/ops.h"
#include "bccmis/p4est/detail/gather.h"

namespace bccmis::p4est_bridge {

namespace {

// "(x, y)" or "(x, y, z)", how the cores' messages name a position.
template <std::size_t N>
std::string join(const std::array<std::int64_t, N>& v, const char* separator) {
  std::string t;
  for (std::size_t a = 0; a < N; ++a) t += (a == 0 ? "" : separator) + std::to_string(v[a]);
  return t;
}

template <int Dim>
std::string describe(const LeafOf<Dim>& leaf) {
  return "the level-" + std::to_string(leaf.level) + " " + P4<Dim>::kCell + " centered at (" +
         join(P4<Dim>::axes(leaf.center), ", ") + ")";
}

template <int Dim>
std::array<std::int32_t, Dim> coordinates(const QuadrantOf<Dim>& q) {
  if constexpr (Dim == 2)
    return {q.x, q.y};
  else
    return {q.x, q.y, q.z};
}

template <int Dim>
QuadrantOf<Dim> quadrant(std::int32_t tree, const std::array<std::int32_t, Dim>& x, std::int32_t level) {
  if constexpr (Dim == 2)
    return {tree, x[0], x[1], level};
  else
    return {tree, x[0], x[1], x[2], level};
}

template <int Dim>
std::string describe(const QuadrantOf<Dim>& q) {
  std::string t = std::string(P4<Dim>::kQuadrant) + " (tree " + std::to_string(q.tree);
  const std::array<std::int32_t, Dim> x = coordinates(q);
  for (std::size_t a = 0; a < Dim; ++a) t += std::string(", ") + "xyz"[a] + " " + std::to_string(x[a]);
  return t + ", level " + std::to_string(q.level) + ")";
}

// The level-k ancestor of a leaf (k <= leaf.level): the cell of side s_k
// containing the leaf's center.
template <int Dim>
LeafOf<Dim> ancestor(const typename P4<Dim>::LatticeSize& size, const LeafOf<Dim>& leaf, int k) {
  const std::int64_t s = cell_side(size, k);
  std::array<std::int64_t, Dim> c = P4<Dim>::axes(leaf.center);
  for (std::int64_t& v : c) v = (v / s) * s + s / 2;
  return {P4<Dim>::point(c), k};
}

// Coarsest first, then by position: the order in which import refines.
template <int Dim>
bool level_first(const LeafOf<Dim>& a, const LeafOf<Dim>& b) {
  return a.level != b.level ? a.level < b.level : a.center < b.center;
}

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

// ---- Brick ---------------------------------------------------------------------------------

template <int Dim>
BrickOf<Dim>::BrickOf(const LatticeSize& size) : size_(size) {
  validate_lattice_size(size);
  if (size.L > Traits::kQMaxLevel)
    throw std::invalid_argument("bccmis::p4est_bridge: L = " + std::to_string(size.L) + " exceeds " + Traits::kMaxName +
                                "_QMAXLEVEL = " + std::to_string(Traits::kQMaxLevel));
  const Cell n = Traits::cells(size);
  std::int64_t trees = 1;
  for (const std::int64_t m : n) {
    if (trees > std::numeric_limits<std::int32_t>::max() / m)
      throw std::invalid_argument("bccmis::p4est_bridge: " + std::string(Traits::kGrid) + " = " + join(n, " x ") +
                                  " trees exceed " + Traits::kP4est + "'s tree index");
    trees *= m;
  }
  shift_ = Traits::kQMaxLevel - size.L;
  std::array<int, Dim> brick{};
  for (std::size_t a = 0; a < Dim; ++a) brick[a] = static_cast<int>(n[a]);
  conn_.reset(Traits::new_brick(brick));
  if (conn_->num_trees != trees)
    throw std::logic_error("bccmis::p4est_bridge: the brick has " + std::to_string(conn_->num_trees) +
                           " trees, expected " + std::to_string(trees));
  // The brick's tree numbering, read from its vertex coordinates: tree t's
  // corners are tree_to_vertex[2^Dim t + v], v = 0..2^Dim - 1 in p4est's
  // z-order (x fastest, then y, then z), so corner v must lie at
  // (i, j, k) + (v & 1, v >> 1 & 1, v >> 2).
  constexpr std::size_t kCorners = std::size_t{1} << Dim;
  tree_of_cell_.assign(static_cast<std::size_t>(trees), -1);
  cell_of_tree_.assign(static_cast<std::size_t>(trees), -1);
  for (std::size_t t = 0; t < static_cast<std::size_t>(trees); ++t) {
    std::array<Cell, kCorners> corner{};
    for (std::size_t v = 0; v < kCorners; ++v) {
      const p4est_topidx_t id = conn_->tree_to_vertex[kCorners * t + v];
      for (std::size_t a = 0; a < Dim; ++a)
        corner[v][a] = std::llround(conn_->vertices[3 * static_cast<std::size_t>(id) + a]);
    }
    const Cell low = corner[0];
    bool unit = true, inside = true;
    for (std::size_t v = 0; v < kCorners; ++v)
      for (std::size_t a = 0; a < Dim; ++a)
        unit = unit && corner[v][a] == low[a] + static_cast<std::int64_t>((v >> a) & 1);
    for (std::size_t a = 0; a < Dim; ++a) inside = inside && low[a] >= 0 && low[a] < n[a];
    if (!unit || !inside || tree_of_cell_[static_cast<std::size_t>(index(low))] != -1)
      throw std::logic_error("bccmis::p4est_bridge: brick tree " + std::to_string(t) + " is not a unit " +
                             Traits::kSquare + " of the " + Traits::kGrid + " grid in z-order corners");
    tree_of_cell_[static_cast<std::size_t>(index(low))] = static_cast<std::int32_t>(t);
    cell_of_tree_[t] = index(low);
  }
}

template <int Dim>
std::int64_t BrickOf<Dim>::index(const Cell& cell) const {
  const Cell n = Traits::cells(size_);
  std::int64_t out = 0;
  for (std::size_t a = Dim; a-- > 0;) out = out * n[a] + cell[a];
  return out;
}

template <int Dim>
std::int32_t BrickOf<Dim>::tree_at(const Cell& cell) const {
  return tree_of_cell_.at(static_cast<std::size_t>(index(cell)));
}

template <int Dim>
QuadrantOf<Dim> BrickOf<Dim>::to_quadrant(const Leaf& leaf) const {
  const std::int64_t S = level0_side(size_);
  const std::int64_t half = cell_side(size_, leaf.level) / 2;
  const Cell c = Traits::axes(leaf.center);
  Cell cell{};
  std::array<std::int32_t, Dim> offset{};
  for (std::size_t a = 0; a < Dim; ++a) {
    cell[a] = (c[a] - half) / S;  // of the lower-left corner
    offset[a] = static_cast<std::int32_t>((c[a] - half - cell[a] * S) << shift_);
  }
  return quadrant<Dim>(tree_at(cell), offset, leaf.level);
}

template <int Dim>
LeafOf<Dim> BrickOf<Dim>::to_leaf(const Quadrant& q) const {
  const Cell n = Traits::cells(size_);
  if (q.tree < 0 || static_cast<std::size_t>(q.tree) >= cell_of_tree_.size())
    throw ImportError("bccmis::p4est_bridge: " + describe(q) + ": no such tree in the " + join(n, " x ") + " brick");
  if (q.level < 0 || q.level > size_.L)
    throw ImportError("bccmis::p4est_bridge: " + describe(q) + ": level " + std::to_string(q.level) +
                      (q.level < 0 ? " is negative" : " is deeper than the lattice's L = " + std::to_string(size_.L)));
  const std::int64_t len = std::int64_t{1} << (Traits::kMaxLevel - q.level);
  const std::array<std::int32_t, Dim> x = coordinates(q);
  for (const std::int32_t v : x)
    if (v < 0 || v >= Traits::kRootLen || v % len != 0)
      throw ImportError("bccmis::p4est_bridge: " + describe(q) + ": not a level-" + std::to_string(q.level) + " " +
                        Traits::kQuadrant + " inside its tree");
  const std::int64_t S = level0_side(size_);
  std::int64_t rest = cell_of_tree_[static_cast<std::size_t>(q.tree)];
  const std::int64_t half = cell_side(size_, q.level) / 2;
  Cell c{};
  for (std::size_t a = 0; a < Dim; ++a) {
    c[a] = (rest % n[a]) * S + (std::int64_t{x[a]} >> shift_) + half;
    rest /= n[a];
  }
  return {Traits::point(c), q.level};
}

// ---- Export ----------------------------------------------------------------------------------

template <class G>
requires(dim_of<G> != 0) std::vector<LeafOf<dim_of<G>>> leaves(const G& g) {
  std::vector<LeafOf<dim_of<G>>> out;
  out.reserve(g.C.size());
  for (const auto& [c, l] : g.level) out.push_back({c, l});
  return out;  // std::map order: sorted by center
}

namespace {

template <int Dim>
struct RefineContext {
  const BrickOf<Dim>* brick;
  std::vector<LeafOf<Dim>> sorted;  // by operator<
};

// Split a quadrant unless it is one of the requested leaves.
template <int Dim>
int refine_to_leaves(typename P4<Dim>::forest_t* forest, p4est_topidx_t tree, typename P4<Dim>::quadrant_t* q) {
  const auto* ctx = static_cast<const RefineContext<Dim>*>(forest->user_pointer);
  try {
    const LeafOf<Dim> leaf = ctx->brick->to_leaf(P4<Dim>::quadrant(tree, *q));
    return std::binary_search(ctx->sorted.begin(), ctx->sorted.end(), leaf) ? 0 : 1;
  } catch (...) {
    return 0;  // cannot happen below maxlevel L; make_forest then reports the mismatch
  }
}

}  // namespace

template <int Dim>
ForestPtrOf<Dim> make_forest(const BrickOf<Dim>& brick, std::type_identity_t<std::span<const LeafOf<Dim>>> leaves,
                             sc_MPI_Comm comm) {
  using T = P4<Dim>;
  RefineContext<Dim> ctx{&brick, std::vector<LeafOf<Dim>>(leaves.begin(), leaves.end())};
  std::sort(ctx.sorted.begin(), ctx.sorted.end());
  ctx.sorted.erase(std::unique(ctx.sorted.begin(), ctx.sorted.end()), ctx.sorted.end());
  ForestPtrOf<Dim> forest(T::new_ext(comm, brick.connectivity(), 0, 0, 1, 0, nullptr, &ctx));
  T::refine_ext(forest.get(), 1, brick.size().L, refine_to_leaves<Dim>, nullptr, nullptr);
  forest->user_pointer = nullptr;
  // Every forest leaf is a requested leaf, and there are as many: the leaves
  // tile the lattice. Decided collectively, so every rank throws or none.
  long local_bad = 0;
  for (const QuadrantOf<Dim>& q : local_quadrants(forest.get()))
    if (!std::binary_search(ctx.sorted.begin(), ctx.sorted.end(), brick.to_leaf(q))) ++local_bad;
  long bad = 0;
  MPI_Allreduce(&local_bad, &bad, 1, MPI_LONG, MPI_SUM, comm);
  if (bad != 0 || static_cast<std::size_t>(forest->global_num_quadrants) != ctx.sorted.size())
    throw ImportError("bccmis::p4est_bridge: the " + std::to_string(ctx.sorted.size()) + " leaves do not tile the " +
                      T::kWhich + "lattice (the forest refined to them has " +
                      std::to_string(forest->global_num_quadrants) + " leaves, " + std::to_string(bad) +
                      " of them not requested)");
  return forest;
}

template <int Dim>
ForestPtrOf<Dim> export_forest(const BrickOf<Dim>& brick, const typename P4<Dim>::Graph& g, sc_MPI_Comm comm) {
  if (!(g.size == brick.size()))
    throw std::invalid_argument(std::string("bccmis::p4est_bridge: the ") + P4<Dim>::kWhich +
                                "graph and the brick differ in size");
  const std::vector<LeafOf<Dim>> all = leaves(g);
  return make_forest(brick, all, comm);
}

template <class Forest>
requires(dim_of<Forest> != 0) std::vector<QuadrantOf<dim_of<Forest>>> local_quadrants(const Forest* forest) {
  constexpr int Dim = dim_of<Forest>;
  using T = P4<Dim>;
  std::vector<QuadrantOf<Dim>> out;
  out.reserve(static_cast<std::size_t>(forest->local_num_quadrants));
  if (forest->first_local_tree < 0) return out;  // this rank holds no quadrant
  for (p4est_topidx_t t = forest->first_local_tree; t <= forest->last_local_tree; ++t) {
    sc_array_t* qs = &T::tree_at(forest->trees, t)->quadrants;
    for (std::size_t k = 0; k < qs->elem_count; ++k) {
      const typename T::quadrant_t* q = T::quadrant_at(qs, k);
      out.push_back(T::quadrant(t, *q));
    }
  }
  return out;
}

template <class Forest>
requires(dim_of<Forest> != 0) std::vector<QuadrantOf<dim_of<Forest>>> gather_quadrants(const Forest* forest, int root) {
  static_assert(sizeof(QuadrantOf<dim_of<Forest>>) == (dim_of<Forest> + 2) * sizeof(std::int32_t));
  return detail::gather(local_quadrants(forest), forest->mpicomm, root);
}

// ---- Import ----------------------------------------------------------------------------------

template <class Size>
requires(dim_of<Size> != 0) typename P4<dim_of<Size>>::Graph
    import_leaves(const Size& size, std::type_identity_t<std::span<const LeafOf<dim_of<Size>>>> input) {
  constexpr int Dim = dim_of<Size>;
  using T = P4<Dim>;
  using LeafT = LeafOf<Dim>;
  const std::string lattice = std::string(T::kWhich) + "lattice";
  validate_lattice_size(size);
  std::vector<LeafT> sorted(input.begin(), input.end());
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 1; k < sorted.size(); ++k)
    if (sorted[k] == sorted[k - 1])
      throw ImportError("bccmis::p4est_bridge: " + describe(sorted[k]) + " is listed twice");
  // Every proper ancestor of a leaf is a refined cell of the lattice.
  std::vector<LeafT> refined;
  std::array<std::int64_t, Dim> extent = T::cells(size);
  for (std::int64_t& e : extent) e *= level0_side(size);
  for (const LeafT& leaf : sorted) {
    if (leaf.level < 0 || leaf.level > size.L)
      throw ImportError("bccmis::p4est_bridge: " + describe(leaf) + ": level outside 0.." + std::to_string(size.L));
    const std::int64_t s = cell_side(size, leaf.level);
    const std::array<std::int64_t, Dim> c = T::axes(leaf.center);
    for (std::size_t a = 0; a < Dim; ++a)
      if (c[a] <= 0 || c[a] >= extent[a] || (c[a] - s / 2) % s != 0)
        throw ImportError("bccmis::p4est_bridge: " + describe(leaf) + " is not a " + T::kCell + " of the " + lattice);
    for (int k = 0; k < leaf.level; ++k) refined.push_back(ancestor<Dim>(size, leaf, k));
  }
  std::sort(refined.begin(), refined.end());
  refined.erase(std::unique(refined.begin(), refined.end()), refined.end());
  for (const LeafT& leaf : sorted)
    if (std::binary_search(refined.begin(), refined.end(), leaf))
      throw ImportError("bccmis::p4est_bridge: leaves overlap: " + describe(leaf) +
                        " is a leaf and contains other leaves");
  // Refine coarsest first. Before level k, every refined cell coarser than k
  // is refined, so a cell coarser than k is a leaf of the input. refine(c)
  // (2D: eq. 3, erratum E4) refuses exactly when a neighbor of c across an
  // edge (3D: a face or an edge) is such a leaf, i.e. when a leaf of level
  // >= k+1 inside c and a leaf of level < k across c's boundary differ by 2
  // or more: the input is not face (3D: edge) balanced.
  std::sort(refined.begin(), refined.end(), level_first<Dim>);
  typename T::Graph g = make_lattice(size);
  for (const LeafT& c : refined) {
    const auto r = refine(g, c.center);
    if (r.refused == RefineRefusal::CoarserNeighbor)
      throw ImportError("bccmis::p4est_bridge: the forest is not " + std::string(T::kBalanced) + ": " + describe(c) +
                        " holds leaves of level " + std::to_string(c.level + 1) + " or finer, but " + T::kNeighbor +
                        " is a leaf coarser than level " + std::to_string(c.level));
    if (!r.applied())
      throw ImportError("bccmis::p4est_bridge: " + describe(c) +
                        " cannot be refined: " + std::string(code(*r.refused)));
  }
  if (g.C.size() != sorted.size()) {
    for (const auto& [c, l] : g.level)
      if (!std::binary_search(sorted.begin(), sorted.end(), LeafT{c, l}))
        throw ImportError("bccmis::p4est_bridge: the leaves do not cover the " + lattice + ": nothing covers " +
                          describe(LeafT{c, l}));
  }
  if (const auto v = find_violation(g))
    throw ImportError("bccmis::p4est_bridge: the imported " + lattice + " fails the checker: " + to_string(*v));
  return g;
}

template <int Dim>
typename P4<Dim>::Graph import_quadrants(const BrickOf<Dim>& brick,
                                         std::type_identity_t<std::span<const QuadrantOf<Dim>>> quadrants) {
  std::vector<LeafOf<Dim>> input;
  input.reserve(quadrants.size());
  for (const QuadrantOf<Dim>& q : quadrants) input.push_back(brick.to_leaf(q));
  return import_leaves(brick.size(), input);
}

template <int Dim>
typename P4<Dim>::Graph import_forest(const BrickOf<Dim>& brick, const typename P4<Dim>::forest_t* forest) {
  using T = P4<Dim>;
  if (forest->global_num_quadrants != forest->local_num_quadrants)
    throw ImportError("bccmis::p4est_bridge: import_forest needs the whole " + std::string(T::kWhich) +
                      "forest on this rank (" + std::to_string(forest->local_num_quadrants) + " of " +
                      std::to_string(forest->global_num_quadrants) + " " + T::kQuadrant + "s); use gather_quadrants");
  if (forest->connectivity->num_trees != brick.connectivity()->num_trees)
    throw ImportError(std::string("bccmis::p4est_bridge: the forest's connectivity is not the ") + T::kWhich +
                      "brick's");
  const std::vector<QuadrantOf<Dim>> qs = local_quadrants(forest);
  return import_quadrants(brick, qs);
}

// ---- The instantiations: p4est (2D) and p8est (3D) -------------------------------------------

#define BCCMIS_P4EST_INSTANTIATE(Dim)                                                                    \
  template class BrickOf<Dim>;                                                                           \
  template std::vector<LeafOf<Dim>> leaves(const P4<Dim>::Graph&);                                       \
  template ForestPtrOf<Dim> make_forest(const BrickOf<Dim>&, std::span<const LeafOf<Dim>>, sc_MPI_Comm); \
  template ForestPtrOf<Dim> export_forest(const BrickOf<Dim>&, const P4<Dim>::Graph&, sc_MPI_Comm);      \
  template std::vector<QuadrantOf<Dim>> local_quadrants(const P4<Dim>::forest_t*);                       \
  template std::vector<QuadrantOf<Dim>> gather_quadrants(const P4<Dim>::forest_t*, int);                 \
  template P4<Dim>::Graph import_quadrants(const BrickOf<Dim>&, std::span<const QuadrantOf<Dim>>);       \
  template P4<Dim>::Graph import_leaves(const P4<Dim>::LatticeSize&, std::span<const LeafOf<Dim>>);      \
  template P4<Dim>::Graph import_forest(const BrickOf<Dim>&, const P4<Dim>::forest_t*);

BCCMIS_P4EST_INSTANTIATE(2)
BCCMIS_P4EST_INSTANTIATE(3)

#undef BCCMIS_P4EST_INSTANTIATE

}  // namespace bccmis::p4est_bridge
