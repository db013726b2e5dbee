// `bccmis stuff --animate` as a library call (animate_shape.h; spec/stuffing.md S14-S16).
#include "bccmis/stuff/animate_shape.h"

#include <optional>
#include <string>

#include "bccmis/json_writer.h"
#include "bccmis/stuff/mesh_shape.h"
#include "bccmis/stuff/stopwatch.h"

namespace bccmis::stuff {

Vec3 default_path(const Shape& shape) {
  const Bounds b = shape.bounds();
  return {1.5 * (b.hi[0] - b.lo[0]), 0, 0};
}

Vec3 frame_offset(const Vec3& path, int k, int frames) {
  return {path[0] * k / frames, path[1] * k / frames, path[2] * k / frames};
}

std::string empty_frame_message(const Shape& shape, int k, const Fit& fit) {
  return shape.describe() + ": frame " + std::to_string(k) + ": the mesh is empty: " + level_hint(shape.bounds(), fit);
}

Fit fit_moving(const Shape& shape, const Vec3& path, const StuffOptions& options) {
  const Fit fit = fit_lattice(swept_bounds(shape, path), options);
  check_moving_fit(fit);
  return fit;
}

std::optional<std::string> swept_box_notice(const Shape& shape, const Vec3& path, const StuffOptions& options) {
  const double swept = fit_lattice(swept_bounds(shape, path), options).h;
  const double still = fit_lattice(shape.bounds(), options).h;
  if (!(swept > still)) return std::nullopt;
  return "--animate fits the lattice to the swept box: finest side " + JsonWriter::number(swept) + " against " +
         JsonWriter::number(still) + " for the shape alone";
}

AnimationSummary animate_shape(const std::shared_ptr<const Shape>& shape, const AnimateSettings& settings,
                               const std::function<void(const Frame&)>& on_frame, const Progress& progress) {
  const Fit fit = fit_moving(*shape, settings.path, settings.lattice);
  // S14: the lattice is fitted to the swept box; say what that costs.
  if (progress)
    if (const auto notice = swept_box_notice(*shape, settings.path, settings.lattice)) progress(*notice);
  const StuffOptions& options = settings.lattice;
  const int n = settings.frames;
  const auto t0 = Clock::now();
  MovingLattice moving(shape, fit, options);
  const double initial = seconds_since(t0);
  AnimationSummary summary;
  double step_total = 0, scratch_total = 0;
  for (int k = 0; k <= n; ++k) {
    Frame frame;
    frame.index = k;
    const Vec3 offset = frame_offset(settings.path, k, n);
    if (k == 0) {
      frame.report.leaves = moving.lattice().cell_count();
      frame.report.lattice_seconds = initial;
    } else {
      frame.report = moving.step(offset);
      step_total += frame.report.lattice_seconds + frame.report.stuff_seconds;
      summary.operations += frame.report.refines + frame.report.coarsens;
    }
    if (settings.compare || settings.check) {
      const auto t = Clock::now();
      const auto moved = translated(shape, offset);
      const d3::fast::Lattice g = background_fast(*moved, fit, options);
      const Stuffed s = stuff(*moved, fit, g, options);
      frame.scratch_seconds = seconds_since(t);
      if (k > 0) scratch_total += frame.scratch_seconds;
      if (settings.check) {
        const std::string at = "frame " + std::to_string(k) + ": ";
        if (!(g.to_graph() == moving.lattice().to_graph()))
          throw CheckError(at + "the lattice updated locally differs from the one built from scratch");
        if (!same_tetrahedra(s.mesh, moving.stuffed().mesh))
          throw CheckError(at + "the mesh stuffed again locally differs from the one stuffed from scratch");
        if (auto why = find_stuffed_problem(moving.shape(), fit, moving.stuffed().mesh)) throw CheckError(at + *why);
      }
    }
    frame.mesh = &moving.stuffed().mesh;
    // S26: a frame without tetrahedra is bad input for this level.
    if (frame.mesh->tets.empty()) throw ShapeError(empty_frame_message(*shape, k, fit));
    on_frame(frame);
  }
  summary.mean_step_seconds = step_total / n;
  summary.mean_scratch_seconds = scratch_total / n;
  return summary;
}

}  // namespace bccmis::stuff
