// bccmis::stuff: a shape moving through a fixed lattice (spec/stuffing.md
// S14-S16): per frame, refine where the surface arrived and coarsen where it
// left, by local lattice operations, then stuff again only the leaves whose
// tetrahedra can have changed.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "bccmis/fast/d3/lattice.h"
#include "bccmis/stuff/detail/distance_bound.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

/// What one frame did (S15, S16).
struct FrameReport {
  std::size_t refines = 0;   ///< refine operations (the cascade's included)
  std::size_t coarsens = 0;  ///< coarsen operations
  std::size_t leaves = 0;
  std::size_t restuffed_leaves = 0;      ///< S16's dirty leaves
  std::size_t restuffed_tetrahedra = 0;  ///< their lattice tetrahedra, stuffed again
  double lattice_seconds = 0, stuff_seconds = 0;
};

/// S14: the box a shape covers when translated by t d for t in [0, 1].
Bounds swept_bounds(const Shape& shape, const Vec3& d);

/// S16: throws ShapeError when the lattice has 2^21 or more lattice points
/// along a side (the moving lattice's pool packs 21 bits a coordinate).
void check_moving_fit(const Fit& fit);

/// S15, S16: the lattice of background() and its stuffing kept up to date
/// under a moving shape, on the fast lattice (d3::fast::Lattice).
class MovingLattice {
 public:
  /// The lattice of background_fast(shape at offset 0, fit, options), stuffed.
  MovingLattice(std::shared_ptr<const Shape> shape, const Fit& fit, const StuffOptions& options);
  /// Moves the shape to `offset` (from its own position): refines the cells
  /// the surface came near, coarsens the parents it left (S15), and stuffs
  /// again the leaves whose tetrahedra can have changed (S16).
  FrameReport step(const Vec3& offset);
  const d3::fast::Lattice& lattice() const { return g_; }
  /// The mesh of the current frame: the same tetrahedra (vertex positions,
  /// kinds and levels) as stuff() on this lattice, in another order;
  /// lattice_tetrahedra counts those of the leaves that are not outside.
  const Stuffed& stuffed() const { return stuffed_; }
  /// The shape at the current offset.
  const Shape& shape() const { return *moved_; }

 private:
  /// What S16 keeps of a leaf between frames.
  struct Leaf {
    std::vector<d3::Tet> lattice;  ///< its tetrahedra (spec/mesh3d.md)
    /// Inside and inactive: its tetrahedra as output, on the point pool.
    std::vector<std::array<std::uint32_t, 4>> inside;
    bool stale = true;  ///< `lattice` not computed since the lattice changed here
    int level = -1;
  };

  /// A leaf S16 classifies again: whether its lattice tetrahedra changed,
  /// and what is known of its distance to the surface (S37).
  struct Candidate {
    d3::Point u;
    bool relattice = false;
    detail::DistanceBound f;
    /// Found by the descent: |f| <= max(s + 1.05 r_w, m) (S16, S38a).
    bool near = false;
    /// A changed cell of this step or a child of one (S38a).
    bool born = false;
  };

  /// What the frame's descent collects (S15, S16).
  struct Descent {
    double moved = 0;  ///< the distance moved since the last frame, with a margin
    std::vector<std::pair<d3::Point, int>> failing, deferred;
    std::vector<Candidate> near;
  };

  std::int64_t side(int level) const { return d3::cell_side(fit_.size, level); }
  std::vector<d3::Point> roots() const;
  void refine_visit(const d3::Point& c, int level, const detail::DistanceBound& parent, FrameReport& report,
                    Descent& d);
  bool coarsen_subtree(const d3::Point& c, int level, FrameReport& report);
  void near_visit(const d3::Point& c, int level, const detail::DistanceBound& parent, double moved,
                  std::vector<Candidate>& out);
  /// S38: what f's bound at a cell of `level` says of f at its children's
  /// centers.
  detail::DistanceBound to_children(const detail::DistanceBound& f, int level) const;
  /// S37: what the distances asked before say of |f(p)| now.
  detail::DistanceBound remembered(const d3::Point& p) const;
  /// S37, S38, S39: `parent` with what the distances asked before say of
  /// |f(p)| now.
  detail::DistanceBound known(const d3::Point& p, const detail::DistanceBound& parent) const;
  /// S37, S38, S39: whether |f(p)| <= t, when `f` decides it (lowered by
  /// its point of the surface if need be, S39).
  std::optional<bool> decide(const d3::Point& p, detail::DistanceBound& f, double t) const;
  /// S37: whether |f(p)| <= t, from `f` when it decides, else asked of the
  /// shape (f then the value, remembered).
  bool at_most(const d3::Point& p, detail::DistanceBound& f, double t);
  bool leaf_at(const d3::Point& p, const std::array<int, 3>& octant, int from, d3::Point& out) const;
  std::vector<d3::Point> lattice_dirty();
  /// `descended`: the candidates follow a descent, which found every leaf
  /// near the surface (S38a); else every candidate's activity is asked.
  void restuff(const std::vector<Candidate>& candidates, bool descended, FrameReport& report);
  void release(Leaf& leaf);
  std::uint32_t acquire(const d3::Point& p);
  void assemble(const StuffedPart& part);

  std::shared_ptr<const Shape> shape_;
  std::shared_ptr<const Shape> moved_;
  Fit fit_;
  StuffOptions options_;
  d3::fast::Lattice g_;
  /// S16: how far from the surface a warped vertex can be.
  double reach_;
  Vec3 offset_{};
  /// The cells refined or coarsened in this step, with their levels.
  std::vector<std::pair<d3::Point, int>> changed_;
  std::unordered_map<d3::Point, Leaf, d3::PointHash> leaves_;
  std::vector<d3::Point> active_;  ///< S16's active leaves of the last frame
  /// Packed lattice point -> pool index: open addressing with linear
  /// probing, deletion by backward shift.
  class PackedIndex {
   public:
    static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
    std::uint32_t find(std::uint64_t k) const;
    /// The value of k, first set to v if k was absent; and whether it was.
    std::pair<std::uint32_t, bool> insert(std::uint64_t k, std::uint32_t v);
    void erase(std::uint64_t k);

   private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // no packed point (bit 63 is 0)
    std::size_t home(std::uint64_t k) const;
    void grow();
    std::vector<std::uint64_t> keys_;
    std::vector<std::uint32_t> values_;
    std::size_t used_ = 0;
  };
  // The lattice points of the inside leaves' tetrahedra, counted.
  PackedIndex index_;
  /// S37: each point asked, its distance and the offset it was asked at;
  /// S39: a point of the surface at that distance, when the shape gave one.
  struct Asked {
    double f;
    Vec3 at;
    std::optional<Vec3> nearest;
  };
  PackedIndex asked_index_;
  std::vector<Asked> asked_;
  bool lipschitz_ = false;         ///< S37 fact 1: the shape's distance() is 1-Lipschitz
  double rounding_ = 0;            ///< S37 fact 2: e
  bool surface_distance_ = false;  ///< S39a: |f| is the distance to the surface
  std::vector<d3::Point> point_;
  std::vector<std::uint32_t> refs_;
  std::vector<std::uint32_t> free_;
  std::vector<d3::Tet> tets_;  ///< the active leaves' lattice tetrahedra (kept for its capacity)
  Stuffed stuffed_;
};

}  // namespace bccmis::stuff
