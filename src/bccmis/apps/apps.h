// bccmis apps: the two applications of Erleben 2009, §3, as tools.
//
//   run_heightfield  adaptive tessellation of a height field (Fig. 4 and 5)
//   run_animate      a moving feature refines the lattice around it (Fig. 6)
//
// The CLI (`bccmis heightfield`, `bccmis animate`) fills these option
// structs one flag per field and calls the run functions; spec/apps.md
// describes both tools, their balance mode and their output formats. The
// building blocks are in balance.h, heightfield.h, image.h, mesh.h and
// animate.h; the apps use only the public API of the reference core.
//
// Exit codes of the run functions: 0 ok; 1 an invariant was violated (only
// with `check`); 2 bad input (options, unreadable or malformed image or
// state, unwritable output); 3 internal error. Errors go to `err` as one line
// starting with `bccmis heightfield: ` or `bccmis animate: `.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "bccmis/graph.h"

namespace bccmis {

/// `bccmis heightfield`: tessellate a height-field image.
///
/// Outputs: every path field below is optional; "" writes nothing and "-"
/// writes to `out`. At most one output may be "-" (stats included).
struct HeightfieldOptions {
  /// input: the image, a PGM (P2/P5, 8/16-bit, any maxval) or a PNG (8/16-bit
  /// gray or colour, converted to luminance; only when built with stb).
  /// "-" reads standard input. Required; no default.
  std::string input;
  /// width: initial lattice width W in level-0 cells (1..1024). Default 6 (the paper's 6x6).
  /// Ignored with `from`.
  std::int64_t width = 6;
  /// height: initial lattice height H in level-0 cells (1..1024). Default 6. Ignored with `from`.
  std::int64_t height = 6;
  /// max_level: the lattice's maximum refinement level L (0..24). Default 5. Ignored with `from`.
  int max_level = 5;
  /// vertical_scale: a pixel's height is its sample / maxval times this (> 0). Default 1.0.
  /// x and y of the outputs are in level-0 cell units (the domain is W x H).
  double vertical_scale = 1.0;
  /// tolerance: refine a cell whose error is above this, in height units (>= 0). Default 0.02.
  double tolerance = 0.02;
  /// measure: the cell error, "max" (max |interpolated - pixel| over every pixel
  /// in the cell; exact) or "samples" (the paper's: max error at `samples`
  /// random points of the cell). Default "max".
  std::string measure = "max";
  /// samples: random points per cell for measure "samples" (1..100000). Default 16.
  int samples = 16;
  /// seed: seed of the "samples" measure; the points of a cell depend only on
  /// the seed and the cell. Default 1.
  std::uint64_t seed = 1;
  /// balance: the 2:1 level rule, "edge" (cells sharing a side piece; the
  /// core's rule) or "corner" (cells touching at a corner point too; needs a
  /// corner-balanced `from` state). Default "edge".
  std::string balance = "edge";
  /// sweeps: stop after this many sweeps (>= 0); 0 means until nothing changes. Default 0.
  int sweeps = 0;
  /// impl: the lattice implementation that runs the tessellation,
  /// "reference" (src/bccmis, std::set) or "fast" (src/fast, flat arrays).
  /// Both make the same decisions, so every output is the same; only
  /// tessellate_seconds differs. Default "reference".
  std::string impl = "reference";
  /// from: a canonical state to start from instead of the initial lattice
  /// (incremental re-tessellation: cells whose merged error is within the
  /// tolerance are coarsened first, then refinement sweeps run). Default "" (none).
  std::string from;
  /// obj: Wavefront OBJ of the 3D triangle mesh. Default "".
  std::string obj;
  /// ply: ASCII PLY of the mesh, with the level of each triangle's cell. Default "".
  std::string ply;
  /// vtu: VTK XML unstructured grid (ParaView), level and error as cell data. Default "".
  std::string vtu;
  /// svg: top view, cells shaded by level (render_svg). Default "".
  std::string svg;
  /// state: the final canonical state (spec/formats.md). Default "".
  std::string state;
  /// stats: where the statistics go (N, C, operations O, sweeps, max/RMS
  /// error, time). Default "-" (out).
  std::string stats = "-";
  /// json: statistics as one JSON object instead of `name value` lines. Default false.
  bool json = false;
  /// check: run the invariant checker (and, with corner balance, the corner
  /// check) after every sweep; exit 1 on a violation. Default false.
  bool check = false;
  /// progress: per-sweep progress lines on `err`: "auto" (when `err` is
  /// std::cerr on a terminal and the image has at least 65536 pixels),
  /// "always" or "never". Default "auto".
  std::string progress = "auto";
  /// quiet: no one-line summary on `err` at the end. Default false.
  bool quiet = false;
};

/// Runs `bccmis heightfield`. Returns the exit code (see the top of this file).
int run_heightfield(const HeightfieldOptions& options, std::ostream& out, std::ostream& err);

/// `bccmis animate`: a disk moves along a path; every frame refines the cells
/// meeting it to the target level (balanced) and coarsens cells it has left.
struct AnimateOptions {
  /// width: lattice width W in level-0 cells (1..1024). Default 8.
  std::int64_t width = 8;
  /// height: lattice height H in level-0 cells (1..1024). Default 8.
  std::int64_t height = 8;
  /// max_level: the lattice's maximum level L (0..24). Default 5.
  int max_level = 5;
  /// target_level: level of the cells meeting the feature (0..L); -1 means L. Default -1.
  int target_level = -1;
  /// radius: the feature's radius in level-0 cell units (>= 0; 0 is a point). Default 0.5.
  double radius = 0.5;
  /// path: the feature's path, `x,y;x,y;...` in level-0 cell units (the
  /// domain is [0, W] x [0, H]); it moves at constant speed along it.
  /// Default "1,4;4,7;7,4;4,1;1,4" (a diamond loop in the default 8x8 lattice).
  std::string path = "1,4;4,7;7,4;4,1;1,4";
  /// balance: the 2:1 level rule, "edge" or "corner" (see HeightfieldOptions::balance). Default "edge".
  std::string balance = "edge";
  /// frames: number of frames (1..100000); frame k is at fraction k/(frames-1) of the path. Default 40.
  int frames = 40;
  /// lift: after the last frame, one more frame without the feature (the
  /// lattice returns to the initial one). Default false.
  bool lift = false;
  /// impl: the lattice implementation, "reference" or "fast" (see
  /// HeightfieldOptions::impl): the same frames, operations and states.
  /// Default "reference".
  std::string impl = "reference";
  /// svg_dir: write frame_0000.svg, frame_0001.svg, ... into this existing
  /// directory (render_svg, the feature drawn as a circle). Default "" (none).
  std::string svg_dir;
  /// state: the final canonical state. Default "" (none); "-" is `out`.
  std::string state;
  /// stats: per-frame statistics (frame, position, refinements, coarsenings,
  /// cells, nodes, time) and totals. Default "-" (out).
  std::string stats = "-";
  /// json: statistics as one JSON object. Default false.
  bool json = false;
  /// check: run the invariant checker (and, with corner balance, the corner
  /// check) after every frame; exit 1 on a violation. Default false.
  bool check = false;
  /// quiet: no one-line summary on `err` at the end. Default false.
  bool quiet = false;
};

/// Runs `bccmis animate`. Returns the exit code (see the top of this file).
int run_animate(const AnimateOptions& options, std::ostream& out, std::ostream& err);

// ---- The same as library calls (no files, no streams) --------------------------

/// One frame of an animation.
struct FrameReport {
  int frame = 0;               ///< 0-based
  bool lifted = false;         ///< the extra frame without the feature (AnimateOptions::lift)
  double x = 0, y = 0;         ///< feature center, level-0 cell units
  std::size_t refinements = 0;
  std::size_t coarsenings = 0;
  std::size_t cells = 0;
  std::size_t nodes = 0;
  double seconds = 0;          ///< wall time of the frame's adaptation
};

/// Called after every frame with its report and the lattice (with the fast
/// implementation, a reference copy of it, made only when an observer is set).
using FrameObserver = std::function<void(const FrameReport& report, const Graph& g)>;

/// The animation of `options` (its output fields are ignored). Throws
/// std::invalid_argument on invalid options. Returns the final lattice;
/// `reports`, when given, receives one report per frame.
Graph animate(const AnimateOptions& options, const FrameObserver& after_frame = {},
              std::vector<FrameReport>* reports = nullptr);

}  // namespace bccmis
