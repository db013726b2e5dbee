// bccmis apps: adaptive tessellation of a height field (Erleben 2009, §3,
// Fig. 4 and 5). The image is stretched over the lattice's domain; every cell
// is interpolated piecewise linearly on its triangle fan (center + boundary
// nodes in angular order, heights sampled at the vertex positions), and cells
// whose error is above a tolerance are refined with refine_balanced, sweep by
// sweep, until nothing changes (spec/apps.md, "Height-field tessellation").
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "bccmis/apps/balance.h"
#include "bccmis/apps/image.h"
#include "bccmis/graph.h"

namespace bccmis {

/// The height field over a lattice's domain [0, W*S] x [0, H*S]. Pixel
/// (col, row) sits at x = col * W*S / (width-1), y = (height-1-row) * H*S /
/// (height-1): the image's corners are the domain's corners and the image's
/// top row is at y = H*S. Between pixels the field is bilinear. Heights are
/// the normalized samples times `vertical_scale`.
class HeightSampler {
 public:
  /// Throws std::invalid_argument unless the field is at least 2x2 and
  /// holds width*height values.
  HeightSampler(const HeightField& field, const LatticeSize& size, double vertical_scale);

  /// The bilinear height at a point of the domain (lattice units).
  double at(double x, double y) const;
  double at(const Point& p) const { return at(static_cast<double>(p.x), static_cast<double>(p.y)); }

  /// The pixel columns whose x lies in [x0, x1] (or [x0, x1) when `half_open`
  /// and x1 is not the domain's right side); empty when lo > hi.
  std::pair<std::int64_t, std::int64_t> columns(std::int64_t x0, std::int64_t x1, bool half_open) const;
  /// The same for pixel rows counted from the bottom (j = height-1-row).
  std::pair<std::int64_t, std::int64_t> rows(std::int64_t y0, std::int64_t y1, bool half_open) const;
  double column_x(std::int64_t col) const;
  double row_y(std::int64_t j) const;  ///< j counted from the bottom
  /// The pixel's height (normalized sample times vertical_scale), j from the bottom.
  double pixel(std::int64_t col, std::int64_t j) const;

  const HeightField& field() const { return *field_; }
  const LatticeSize& size() const { return size_; }
  double vertical_scale() const { return scale_; }

 private:
  const HeightField* field_;
  LatticeSize size_;
  double scale_;
  std::int64_t domain_w_, domain_h_;
};

/// How a cell's error is measured.
enum class ErrorMeasure {
  MaxPixel,       ///< `max`: max |interpolated - pixel| over every pixel in the closed cell (exact, deterministic)
  RandomSamples,  ///< `samples`: the paper's measure: max error at `samples` uniform random points of the cell,
                  ///< the field bilinear there; the points depend only on (seed, cell center)
};

/// `max` or `samples`; empty for anything else.
std::optional<ErrorMeasure> parse_error_measure(std::string_view name);
std::string_view name(ErrorMeasure m);

struct ErrorSettings {
  ErrorMeasure measure = ErrorMeasure::MaxPixel;
  int samples = 16;        ///< random points per cell (RandomSamples)
  std::uint64_t seed = 1;  ///< RandomSamples seed
};

/// The piecewise-linear interpolant of one cell: its fan of triangles
/// (center, b_i, b_i+1) over the boundary nodes in counter-clockwise order.
class CellFan {
 public:
  CellFan(const Point& center, int level, std::vector<Point> boundary_ccw, const HeightSampler& s);
  /// The interpolated height at a point of the closed cell.
  double at(double x, double y) const;
  Point center() const { return center_; }
  int level() const { return level_; }
  std::int64_t half_side() const { return half_; }

 private:
  Point center_;
  int level_;
  std::int64_t half_;
  double zc_;
  std::vector<Point> ring_;
  std::vector<double> z_;
};

/// The fan of cell c of g.
CellFan cell_fan(const Graph& g, const Point& c, const HeightSampler& s);

/// A cell's error under `e` (see ErrorMeasure).
double cell_error(const CellFan& fan, const HeightSampler& s, const ErrorSettings& e);
double cell_error(const Graph& g, const Point& c, const HeightSampler& s, const ErrorSettings& e);

/// The error of the whole mesh against every pixel (each pixel counted once).
struct MeshError {
  double max_abs = 0;       ///< max over all pixels of |interpolated - pixel|
  double rms = 0;           ///< root mean square over all pixels
  std::int64_t pixels = 0;  ///< pixels visited (width * height for a valid lattice)
  Point worst_cell;         ///< center of a cell attaining max_abs
};
MeshError mesh_error(const Graph& g, const HeightSampler& s);
/// The same report from the fast lattice (cells visited in the same order).
MeshError mesh_error(const fast::Lattice& g, const HeightSampler& s);

/// Cell errors up to this fraction of the vertical scale are floating-point
/// rounding: tessellate() refines only cells whose error exceeds
/// tolerance + kRoundingSlack * vertical_scale.
inline constexpr double kRoundingSlack = 1e-12;

/// Settings of tessellate().
struct TessellateSettings {
  double tolerance = 0.02;  ///< refine cells whose error is above this (height units)
  ErrorSettings error;
  int max_sweeps = 0;               ///< stop after this many sweeps; 0: until nothing changes
  bool coarsen = false;             ///< first merge cells whose merged error is within tolerance (re-tessellation)
  Balance balance = Balance::Edge;  ///< the 2:1 rule the cascade and the merges keep
};

/// What tessellate() did.
struct TessellateReport {
  std::size_t refinements = 0;  ///< refine operations applied (cascades included)
  std::size_t coarsenings = 0;  ///< coarsen operations applied
  int sweeps = 0;               ///< sweeps that changed something, coarsening passes included
  bool converged = false;       ///< the last sweep found nothing to change
};

/// Called after every sweep that changed something: sweep number (1-based),
/// the graph, and how many operations the sweep applied.
using SweepObserver = std::function<void(int sweep, const Graph& g, std::size_t operations)>;

/// Adapts g to the field. With `coarsen`, first repeats coarsening passes
/// (merging four cells when the merged cell's error is within tolerance)
/// until none applies. Then refinement sweeps: each sweep measures every
/// cell below the maximum level and refines, with refine_balanced, those
/// whose error is above the tolerance, in sorted order. Stops when a sweep
/// finds nothing to refine, or after max_sweeps sweeps in all.
TessellateReport tessellate(Graph& g, const HeightSampler& s, const TessellateSettings& t,
                            const SweepObserver& observer = {});

/// The same tessellation on the fast implementation (src/bccmis/fast): the same
/// cells measured, refined and merged in the same order, so the final state
/// and the report equal the reference's (tests/apps/heightfield_test.cpp).
using FastSweepObserver = std::function<void(int sweep, const fast::Lattice& g, std::size_t operations)>;
TessellateReport tessellate(fast::Lattice& g, const HeightSampler& s, const TessellateSettings& t,
                            const FastSweepObserver& observer = {});

}  // namespace bccmis
