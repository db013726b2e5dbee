#include "bccmis/p4est/bridge3.h"

#include <p8est_extended.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "bccmis/d3/ops.h"
#include "bccmis/invariants/d3/invariants3.h"
#include "bccmis/p4est/detail/gather.h"

namespace bccmis::p4est_bridge {

using d3::Graph3;
using d3::LatticeSize3;
using d3::Point3;

namespace {

std::string describe(const Leaf3& leaf) {
  return "the level-" + std::to_string(leaf.level) + " cube centered at " + d3::to_string(leaf.center);
}

std::string describe(const Quadrant3& q) {
  return "octant (tree " + std::to_string(q.tree) + ", x " + std::to_string(q.x) + ", y " + std::to_string(q.y) +
         ", z " + std::to_string(q.z) + ", level " + std::to_string(q.level) + ")";
}

std::array<std::int64_t, 3> axes(const Point3& p) { return {p.x, p.y, p.z}; }

std::array<std::int64_t, 3> extents(const LatticeSize3& size) {
  const std::int64_t S = d3::level0_side(size);
  return {size.W * S, size.H * S, size.D * S};
}

// The level-k cube (k <= leaf.level) holding the leaf: its ancestor.
Leaf3 ancestor(const LatticeSize3& size, const Leaf3& leaf, int k) {
  const std::int64_t s = d3::cell_side(size, k);
  auto snap = [s](std::int64_t v) { return (v / s) * s + s / 2; };
  return {{snap(leaf.center.x), snap(leaf.center.y), snap(leaf.center.z)}, k};
}

}  // namespace

void Connectivity3Deleter::operator()(p8est_connectivity_t* c) const noexcept { p8est_connectivity_destroy(c); }
void Forest3Deleter::operator()(p8est_t* p) const noexcept { p8est_destroy(p); }

// ---- Brick3 --------------------------------------------------------------------------------

Brick3::Brick3(const LatticeSize3& size) : size_(size) {
  d3::validate_lattice_size(size);
  if (size.L > P8EST_QMAXLEVEL)
    throw std::invalid_argument("bccmis::p4est_bridge: L = " + std::to_string(size.L) +
                                " exceeds P8EST_QMAXLEVEL = " + std::to_string(P8EST_QMAXLEVEL));
  const std::int64_t limit = std::numeric_limits<std::int32_t>::max();
  if (size.W > limit / size.H || size.W * size.H > limit / size.D)
    throw std::invalid_argument("bccmis::p4est_bridge: W x H x D = " + std::to_string(size.W) + " x " +
                                std::to_string(size.H) + " x " + std::to_string(size.D) +
                                " trees exceed p8est's tree index");
  shift_ = P8EST_QMAXLEVEL - size.L;
  conn_.reset(p8est_connectivity_new_brick(static_cast<int>(size.W), static_cast<int>(size.H), static_cast<int>(size.D),
                                           0, 0, 0));
  const auto trees = static_cast<std::size_t>(size.W * size.H * size.D);
  if (static_cast<std::size_t>(conn_->num_trees) != trees)
    throw std::logic_error("bccmis::p4est_bridge: the brick has " + std::to_string(conn_->num_trees) +
                           " trees, expected " + std::to_string(trees));
  // The numbering is read from the vertex coordinates: tree t's corners are
  // tree_to_vertex[8t + v], v = 0..7 in p8est's z-order (x fastest, then y,
  // then z), so corner v must lie at (i, j, k) + (v & 1, v >> 1 & 1, v >> 2).
  tree_of_cube_.assign(trees, -1);
  cube_of_tree_.assign(trees, -1);
  for (std::size_t t = 0; t < trees; ++t) {
    std::array<std::array<std::int64_t, 3>, 8> corner{};
    for (std::size_t v = 0; v < 8; ++v) {
      const p4est_topidx_t id = conn_->tree_to_vertex[8 * t + v];
      for (std::size_t a = 0; a < 3; ++a)
        corner[v][a] = std::llround(conn_->vertices[3 * static_cast<std::size_t>(id) + a]);
    }
    const std::array<std::int64_t, 3> low = corner[0];
    bool unit_cube = true;
    for (std::size_t v = 0; v < 8; ++v)
      for (std::size_t a = 0; a < 3; ++a)
        unit_cube = unit_cube && corner[v][a] == low[a] + static_cast<std::int64_t>((v >> a) & 1);
    const std::int64_t i = low[0], j = low[1], k = low[2];
    const bool inside = i >= 0 && j >= 0 && k >= 0 && i < size.W && j < size.H && k < size.D;
    const std::int64_t index = (k * size.H + j) * size.W + i;
    if (!unit_cube || !inside || tree_of_cube_[static_cast<std::size_t>(index)] != -1)
      throw std::logic_error("bccmis::p4est_bridge: brick tree " + std::to_string(t) +
                             " is not a unit cube of the W x H x D grid in z-order corners");
    tree_of_cube_[static_cast<std::size_t>(index)] = static_cast<std::int32_t>(t);
    cube_of_tree_[t] = index;
  }
}

std::int32_t Brick3::tree(std::int64_t i, std::int64_t j, std::int64_t k) const {
  return tree_of_cube_.at(static_cast<std::size_t>((k * size_.H + j) * size_.W + i));
}

Quadrant3 Brick3::to_quadrant(const Leaf3& leaf) const {
  const std::int64_t S = d3::level0_side(size_);
  const std::int64_t half = d3::cell_side(size_, leaf.level) / 2;
  const std::array<std::int64_t, 3> c = axes(leaf.center);
  std::array<std::int64_t, 3> cube{}, offset{};
  for (std::size_t a = 0; a < 3; ++a) {
    cube[a] = (c[a] - half) / S;
    offset[a] = (c[a] - half - cube[a] * S) << shift_;
  }
  return {tree(cube[0], cube[1], cube[2]), static_cast<std::int32_t>(offset[0]), static_cast<std::int32_t>(offset[1]),
          static_cast<std::int32_t>(offset[2]), leaf.level};
}

Leaf3 Brick3::to_leaf(const Quadrant3& q) const {
  if (q.tree < 0 || static_cast<std::size_t>(q.tree) >= cube_of_tree_.size())
    throw ImportError("bccmis::p4est_bridge: " + describe(q) + ": no such tree in the " + std::to_string(size_.W) +
                      " x " + std::to_string(size_.H) + " x " + std::to_string(size_.D) + " brick");
  if (q.level < 0 || q.level > size_.L)
    throw ImportError("bccmis::p4est_bridge: " + describe(q) + ": level " + std::to_string(q.level) +
                      (q.level < 0 ? " is negative" : " is deeper than the lattice's L = " + std::to_string(size_.L)));
  const std::int64_t len = std::int64_t{1} << (P8EST_MAXLEVEL - q.level);
  for (const std::int32_t v : {q.x, q.y, q.z})
    if (v < 0 || v >= P8EST_ROOT_LEN || v % len != 0)
      throw ImportError("bccmis::p4est_bridge: " + describe(q) + ": not a level-" + std::to_string(q.level) +
                        " octant inside its tree");
  const std::int64_t S = d3::level0_side(size_);
  const std::int64_t index = cube_of_tree_[static_cast<std::size_t>(q.tree)];
  const std::int64_t i = index % size_.W, j = index / size_.W % size_.H, k = index / (size_.W * size_.H);
  const std::int64_t half = d3::cell_side(size_, q.level) / 2;
  return {{i * S + (std::int64_t{q.x} >> shift_) + half, j * S + (std::int64_t{q.y} >> shift_) + half,
           k * S + (std::int64_t{q.z} >> shift_) + half},
          q.level};
}

// ---- Export ----------------------------------------------------------------------------------

std::vector<Leaf3> leaves(const Graph3& g) {
  std::vector<Leaf3> out;
  out.reserve(g.C.size());
  for (const auto& [c, l] : g.level) out.push_back({c, l});
  return out;  // std::map order: sorted by center
}

namespace {

struct Wanted {
  const Brick3* brick;
  std::vector<Leaf3> sorted;
};

// Split an octant unless it is one of the wanted leaves.
int split_unless_wanted(p8est_t* forest, p4est_topidx_t tree, p8est_quadrant_t* q) {
  const auto* wanted = static_cast<const Wanted*>(forest->user_pointer);
  try {
    const Leaf3 leaf = wanted->brick->to_leaf({tree, q->x, q->y, q->z, q->level});
    return std::binary_search(wanted->sorted.begin(), wanted->sorted.end(), leaf) ? 0 : 1;
  } catch (...) {
    return 0;  // cannot happen below maxlevel L; make_forest then reports the mismatch
  }
}

}  // namespace

Forest3Ptr make_forest(const Brick3& brick, std::span<const Leaf3> leaves, sc_MPI_Comm comm) {
  Wanted wanted{&brick, std::vector<Leaf3>(leaves.begin(), leaves.end())};
  std::sort(wanted.sorted.begin(), wanted.sorted.end());
  wanted.sorted.erase(std::unique(wanted.sorted.begin(), wanted.sorted.end()), wanted.sorted.end());
  Forest3Ptr forest(p8est_new_ext(comm, brick.connectivity(), 0, 0, 1, 0, nullptr, &wanted));
  p8est_refine_ext(forest.get(), 1, brick.size().L, split_unless_wanted, nullptr, nullptr);
  forest->user_pointer = nullptr;
  // The leaves tile the lattice iff every forest leaf was wanted and there
  // are as many. Decided collectively: every rank throws or none does.
  long stray = 0;
  for (const Quadrant3& q : local_quadrants(forest.get()))
    stray += std::binary_search(wanted.sorted.begin(), wanted.sorted.end(), brick.to_leaf(q)) ? 0 : 1;
  long total_stray = 0;
  MPI_Allreduce(&stray, &total_stray, 1, MPI_LONG, MPI_SUM, comm);
  if (total_stray != 0 || static_cast<std::size_t>(forest->global_num_quadrants) != wanted.sorted.size())
    throw ImportError("bccmis::p4est_bridge: the " + std::to_string(wanted.sorted.size()) +
                      " leaves do not tile the 3D lattice (the forest refined to them has " +
                      std::to_string(forest->global_num_quadrants) + " leaves, " + std::to_string(total_stray) +
                      " of them not requested)");
  return forest;
}

Forest3Ptr export_forest(const Brick3& brick, const Graph3& g, sc_MPI_Comm comm) {
  if (!(g.size == brick.size()))
    throw std::invalid_argument("bccmis::p4est_bridge: the 3D graph and the brick differ in size");
  const std::vector<Leaf3> all = leaves(g);
  return make_forest(brick, all, comm);
}

std::vector<Quadrant3> local_quadrants(const p8est_t* forest) {
  std::vector<Quadrant3> out;
  out.reserve(static_cast<std::size_t>(forest->local_num_quadrants));
  if (forest->first_local_tree < 0) return out;  // an empty rank
  for (p4est_topidx_t t = forest->first_local_tree; t <= forest->last_local_tree; ++t) {
    sc_array_t* octants = &p8est_tree_array_index(forest->trees, t)->quadrants;
    for (std::size_t n = 0; n < octants->elem_count; ++n) {
      const p8est_quadrant_t* q = p8est_quadrant_array_index(octants, n);
      out.push_back({t, q->x, q->y, q->z, q->level});
    }
  }
  return out;
}

std::vector<Quadrant3> gather_quadrants(const p8est_t* forest, int root) {
  static_assert(sizeof(Quadrant3) == 5 * sizeof(std::int32_t));
  return detail::gather(local_quadrants(forest), forest->mpicomm, root);
}

// ---- Import ----------------------------------------------------------------------------------

Graph3 import_leaves(const LatticeSize3& size, std::span<const Leaf3> input) {
  d3::validate_lattice_size(size);
  std::vector<Leaf3> given(input.begin(), input.end());
  std::sort(given.begin(), given.end());
  if (const auto twice = std::adjacent_find(given.begin(), given.end()); twice != given.end())
    throw ImportError("bccmis::p4est_bridge: " + describe(*twice) + " is listed twice");
  const std::array<std::int64_t, 3> extent = extents(size);
  std::vector<Leaf3> split;  // every proper ancestor of a leaf
  for (const Leaf3& leaf : given) {
    if (leaf.level < 0 || leaf.level > size.L)
      throw ImportError("bccmis::p4est_bridge: " + describe(leaf) + ": level outside 0.." + std::to_string(size.L));
    const std::int64_t s = d3::cell_side(size, leaf.level);
    const std::array<std::int64_t, 3> c = axes(leaf.center);
    for (std::size_t a = 0; a < 3; ++a)
      if (c[a] <= 0 || c[a] >= extent[a] || (c[a] - s / 2) % s != 0)
        throw ImportError("bccmis::p4est_bridge: " + describe(leaf) + " is not a cube of the 3D lattice");
    for (int k = 0; k < leaf.level; ++k) split.push_back(ancestor(size, leaf, k));
  }
  std::sort(split.begin(), split.end());
  split.erase(std::unique(split.begin(), split.end()), split.end());
  for (const Leaf3& leaf : given)
    if (std::binary_search(split.begin(), split.end(), leaf))
      throw ImportError("bccmis::p4est_bridge: leaves overlap: " + describe(leaf) +
                        " is a leaf and contains other leaves");
  // Coarsest first: before level k, every split cube coarser than k is
  // split, so a cube coarser than k is an input leaf, and the 3D refine
  // refuses `coarser-neighbor` exactly when a face-or-edge neighbour of the
  // level-k cube is such a leaf: a leaf of level >= k+1 inside it and one of
  // level < k sharing a face or edge piece with it, 2 or more levels apart.
  std::stable_sort(split.begin(), split.end(), [](const Leaf3& a, const Leaf3& b) { return a.level < b.level; });
  Graph3 g(size);
  for (const Leaf3& cube : split) {
    const d3::RefineResult r = d3::refine(g, cube.center);
    if (r.refused == RefineRefusal::CoarserNeighbor)
      throw ImportError(
          "bccmis::p4est_bridge: the forest is not edge balanced (2:1 across faces and edges): " + describe(cube) +
          " holds leaves of level " + std::to_string(cube.level + 1) +
          " or finer, but a face-or-edge neighbour is a leaf coarser than level " + std::to_string(cube.level));
    if (!r.applied())
      throw ImportError("bccmis::p4est_bridge: " + describe(cube) +
                        " cannot be refined: " + std::string(code(*r.refused)));
  }
  if (g.C.size() != given.size())
    for (const auto& [c, l] : g.level)
      if (!std::binary_search(given.begin(), given.end(), Leaf3{c, l}))
        throw ImportError("bccmis::p4est_bridge: the leaves do not cover the 3D lattice: nothing covers " +
                          describe(Leaf3{c, l}));
  if (const std::optional<d3::Violation3> v = d3::find_violation(g))
    throw ImportError("bccmis::p4est_bridge: the imported 3D lattice fails the checker: " + d3::to_string(*v));
  return g;
}

Graph3 import_quadrants(const Brick3& brick, std::span<const Quadrant3> quadrants) {
  std::vector<Leaf3> input;
  input.reserve(quadrants.size());
  for (const Quadrant3& q : quadrants) input.push_back(brick.to_leaf(q));
  return import_leaves(brick.size(), input);
}

Graph3 import_forest(const Brick3& brick, const p8est_t* forest) {
  if (forest->global_num_quadrants != forest->local_num_quadrants)
    throw ImportError("bccmis::p4est_bridge: import_forest needs the whole 3D forest on this rank (" +
                      std::to_string(forest->local_num_quadrants) + " of " +
                      std::to_string(forest->global_num_quadrants) + " octants); use gather_quadrants");
  if (forest->connectivity->num_trees != brick.connectivity()->num_trees)
    throw ImportError("bccmis::p4est_bridge: the forest's connectivity is not the 3D brick's");
  const std::vector<Quadrant3> qs = local_quadrants(forest);
  return import_quadrants(brick, qs);
}

}  // namespace bccmis::p4est_bridge
