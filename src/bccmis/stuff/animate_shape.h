// bccmis::stuff::animate_shape: a shape moved along a straight path, its mesh
// kept up to date frame by frame by local lattice operations and local
// stuffing (spec/stuffing.md S14-S16), the entry point of
// `bccmis stuff --animate`.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "bccmis/stuff/animate.h"
#include "bccmis/stuff/mesh_shape.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

struct AnimateSettings {
  StuffOptions lattice;  ///< S2, S3, S6 (the lattice is fitted to the swept box, S14)
  int frames = 1;        ///< steps after frame 0 (> 0)
  Vec3 path{};           ///< the whole motion: frame k is at offset k path / frames
  bool compare = false;  ///< also stuff every frame from scratch, and time it
  bool check = false;    ///< also compare every frame with the one made from scratch, and check it
};

/// One frame, as animate_shape() hands it on.
struct Frame {
  int index = 0;
  FrameReport report;                  ///< frame 0: the leaves and the initial lattice's seconds
  const d3::TetMeshF* mesh = nullptr;  ///< valid during the call only
  double scratch_seconds = 0;          ///< with compare or check
};

struct AnimationSummary {
  double mean_step_seconds = 0;     ///< lattice and stuffing per step, frames 1..N
  double mean_scratch_seconds = 0;  ///< with compare: stuffing from scratch per frame, frames 1..N
  std::size_t operations = 0;       ///< refines and coarsens, frames 1..N
  double speedup() const { return mean_step_seconds > 0 ? mean_scratch_seconds / mean_step_seconds : 0; }
};

/// The default path: 1.5 times the shape's x extent along x.
Vec3 default_path(const Shape& shape);

/// S15: frame k's offset, (k / frames) path, one expression for every
/// caller (the serial animation, the ranks' frames: spec/distributed.md D14).
Vec3 frame_offset(const Vec3& path, int k, int frames);

/// S26 for frame k of an animation: "SHAPE: frame K: the mesh is empty: "
/// and level_hint of the shape's box in `fit`, one message for the serial
/// animation and the ranks' frames (spec/distributed.md D14).
std::string empty_frame_message(const Shape& shape, int k, const Fit& fit);

/// S14: the lattice fitted to the box the shape sweeps. Throws ShapeError
/// as fit_lattice() does, and when the moving lattice cannot hold it (S16).
Fit fit_moving(const Shape& shape, const Vec3& path, const StuffOptions& options);

/// S14: when the lattice fitted to the box the shape sweeps along `path` is
/// coarser than the one fitted to the shape alone, the notice that says so
/// ("--animate fits the lattice to the swept box: finest side H against H0
/// for the shape alone"); else nothing. One message for the serial
/// animation and the ranks' (spec/distributed.md D14); the CLIs print it.
/// Throws ShapeError as fit_lattice() does.
std::optional<std::string> swept_box_notice(const Shape& shape, const Vec3& path, const StuffOptions& options);

/// Frames 0..frames, each handed to `on_frame` as it is made; `progress`,
/// when given, hears swept_box_notice() when there is one (S14). Throws
/// ShapeError as fit_moving() does, and CheckError (mesh_shape.h) when
/// `check` finds a frame that differs from the one made from scratch or
/// fails the checker's stuffed-mesh layer.
AnimationSummary animate_shape(const std::shared_ptr<const Shape>& shape, const AnimateSettings& settings,
                               const std::function<void(const Frame&)>& on_frame, const Progress& progress = {});

}  // namespace bccmis::stuff
