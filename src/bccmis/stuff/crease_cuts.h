// bccmis::stuff::stuff_on_creases: S5-S9 with the cut points near a sharp
// feature placed on it before warping, so that the stencils follow the
// crease (spec/stuffing.md S35.7), guarded so that S10's interval holds.
//
//   const Features f = detect_features(shape.surface_triangles());
//   CreaseCuts report;
//   Stuffed s = stuff_on_creases(shape, fit, options, f, 0.25, &report);
#pragma once

#include <cstddef>
#include <functional>

#include "bccmis/stuff/features.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

/// S35.7's default delta: a cut point within delta h of a curve is placed on it.
inline constexpr double kCreaseCutDistance = 0.25;

/// What S35.7 did.
struct CreaseCuts {
  std::size_t placed = 0;    ///< vertices of the mesh at a placed cut point (a cut point, or a vertex warped onto it)
  std::size_t excluded = 0;  ///< cut edges kept at S5's point after their tetrahedra failed the guard
  std::size_t rounds = 0;    ///< the runs of S5-S9 made, the last one kept
  bool none = false;         ///< the guard gave up: no cut point placed, the mesh S5-S9's exactly
};

/// S35.7: stuff_fitted (fast) with every cut point within `delta` h of a
/// curve of `features` placed on it, the rounds S35.7's guard asks for.
/// Without curves, or with `delta` <= 0: stuff_fitted exactly. `times`
/// receives every round's phases, added up.
Stuffed stuff_on_creases(const Shape& shape, const Fit& fit, const StuffOptions& options, const Features& features,
                         double delta, CreaseCuts* report = nullptr, PhaseTimes* times = nullptr,
                         const std::function<void(std::size_t leaves, double seconds)>& on_lattice = {});

}  // namespace bccmis::stuff
