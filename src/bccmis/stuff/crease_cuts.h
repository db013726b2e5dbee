// bccmis::stuff::stuff_on_creases: S5-S9 with the cut points near a sharp
// feature placed on it before warping, so that the stencils follow the
// crease (spec/stuffing.md S35.7), guarded so that S10's interval holds.
//
//   const Features f = detect_features(shape.surface_triangles());
//   CreaseCuts report;
//   Stuffed s = stuff_on_creases(shape, fit, options, f, 0.25, &report);
//
// stuff_and_conform_on_creases (S35.8) makes that monotone: the meshes
// with and without the placement, each conformed (S30-S35), and the one
// kept conforms every corner and curve the one without it does.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "bccmis/stuff/conform_features.h"
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

/// S35.8's candidates: A without placement, B with every curve, C with the
/// curves B gains only.
enum class CreaseCandidate { without, all_curves, gained_curves };

/// What S35.8 kept.
struct CreaseConformed {
  Stuffed stuffed;                                     ///< the mesh kept, conformed
  std::vector<std::array<std::uint32_t, 3>> boundary;  ///< its S11 boundary, outward (after S35's splits)
  FeatureConformity conformity;                        ///< S30-S35 on it
  CreaseCuts all_curves;                               ///< S35.7 with every curve (B)
  CreaseCandidate kept = CreaseCandidate::without;
  std::size_t placed_kept = 0;  ///< vertices at a placed cut point in the mesh kept (0 for A)
  std::size_t candidates = 1;   ///< the candidates made (1-3)
};

/// S35.8 on a fitted lattice: candidates A, B and (when B is not kept and
/// B conforms a curve A does not) C, each S5-S9 (fast) then
/// conform_features(`h`, `split_edges`, `split_chords`), and the one kept: B when its
/// conformed corners and curves contain A's and are more, else C when
/// likewise, else A (the mesh without S35.7, byte for byte). `times`
/// receives every candidate's S3-S9 phases, added up, `feature_seconds`
/// the seconds of their S30-S35.
CreaseConformed stuff_and_conform_on_creases(const Shape& shape, const Fit& fit, const StuffOptions& options,
                                             const Features& features, double delta, double h, bool split_edges,
                                             bool split_chords, PhaseTimes* times = nullptr,
                                             double* feature_seconds = nullptr,
                                             const std::function<void(std::size_t, double)>& on_lattice = {});

/// S35.8 from candidate A's stuffing on: `without` is S5-S9's mesh on `fit`
/// (stuff_fitted's, or the same mesh gathered from the pieces of several
/// ranks, spec/distributed.md D12), conformed as A; B and C are made here
/// and the one kept as stuff_and_conform_on_creases says (which is
/// stuff_fitted, then this). `times` and `feature_seconds` are added to,
/// not reset.
CreaseConformed conform_on_creases(Stuffed without, const Shape& shape, const Fit& fit, const StuffOptions& options,
                                   const Features& features, double delta, double h, bool split_edges,
                                   bool split_chords, PhaseTimes* times = nullptr, double* feature_seconds = nullptr);

}  // namespace bccmis::stuff
