// bccmis::stuff::conform_features: a stuffed mesh made to hold the sharp
// features of its shape (spec/stuffing.md S30-S35): boundary vertices
// snapped onto the corners and along the curves, boundary edges split onto
// the curves where no path of snapped vertices holds them, each change
// guarded so that S10's dihedral bound holds.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/stuff/features.h"

namespace bccmis::stuff {

/// S11's point data for a boundary vertex moved onto a feature (S30).
inline constexpr std::uint8_t kSnappedVertex = 3;
/// S11's point data for an interior vertex moved to make room for a snap (S34).
inline constexpr std::uint8_t kRoomVertex = 4;

/// What S30 made: the corners and curve pieces it conformed (a loop is
/// split in two pieces), what the checker's feature layer verifies (S32).
struct FeatureConformity {
  std::vector<Vec3> corners;
  std::vector<FeatureCurve> pieces;
  std::size_t corners_conformed = 0;          ///< of Features::corners
  std::size_t curves_conformed = 0;           ///< of Features::curves, every piece conformed
  std::vector<std::size_t> conformed_curves;  ///< their indices in Features::curves, increasing (S35.8)
  std::size_t moves = 0, refused = 0;         ///< the guard's answers (S31)
  std::size_t room_made = 0;                  ///< moves accepted with the interior neighbours moved (S34)
  std::size_t splits = 0;                     ///< boundary edges split onto a crease and kept (S35, S35.11)
  std::size_t chord_splits = 0;               ///< of them, a conformed path's chords split (S35.11)
  std::size_t chord_splits_refused = 0;       ///< chord splits S35.2's test refused (S35.11)
  std::size_t flips = 0;                      ///< 2-3 and 4-4 flips kept, each with a move (S35.9)
  std::size_t splits_undone = 0;              ///< splits undone, their piece still not conformed (S35.4)
  std::size_t moves_undone =
      0;  ///< moves of older vertices made after those splits (S30.2, S34), undone with them (S35.4)
};

/// S30-S31, S34 and S35 on `mesh` (a stuffed mesh, positively oriented
/// tetrahedra, whose boundary triangles are `boundary`), `h` the finest
/// side: moves boundary vertices onto `features` and marks them
/// kSnappedVertex; S35's splits append vertices (kSnappedVertex) and
/// tetrahedra, and change tetrahedra at the split edges, so that `boundary`
/// is the mesh's only while `splits` is 0. A piece its splits do not
/// conform is left as if they had not been tried (S35.4), then tried from
/// its other end, undone alike (S35.5); `split_edges` false: none of S35
/// (S30-S34 only). S35.9: run again with every move S31 and S34 refuse
/// tried once more after 2-3 and 4-4 flips of the failing tetrahedra at its
/// vertex (the boundary and the volume unchanged, tetrahedra changed and
/// appended), that run kept only when it gains on the first (gains_on);
/// S35.10: a third run, where a move those flips do not let through is
/// tried after a sequence of up to 3 flips, kept only when it gains on the
/// run kept; `flip` false: the first run only. S35.11: a conformed piece's
/// chords split at the input feature points off them (`split_chords`,
/// with `split_edges`).
FeatureConformity conform_features(d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& boundary,
                                   const Features& features, double h, bool split_edges = true, bool flip = true,
                                   bool split_chords = true);

/// S35.11's tolerance, in units of h: a chord is split at an input feature
/// point more than this far from it.
inline constexpr double kChordTolerance = 1e-9;

/// S35.11: of the vertices of C's polyline strictly between arc lengths
/// `s_from` and `s_to`, the one farthest from the segment ab (the first on
/// a tie) when it is more than `tolerance` from it; -1 otherwise.
std::int64_t chord_split_vertex(const FeatureCurve& C, const Vec3& a, const Vec3& b, double s_from, double s_to,
                                double tolerance);

/// S35.8's and S35.9's test: x's conformed corners and curves contain a's,
/// and are more.
bool gains_on(const FeatureConformity& x, const FeatureConformity& a);

/// S30.1: the radius within which a corner's candidates are sought, given
/// the distance `nearest` from the corner to its nearest free boundary
/// vertex (HUGE_VAL when none within 2 h): h when nearest <= h, else 2 h.
double corner_search_radius(double nearest, double h);

/// S33: the largest distance from a point of a feature curve's polyline to
/// the nearest edge of the boundary triangles; 0 without features. `h`
/// (the finest side) sizes the search grid only.
double feature_distance(const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& boundary,
                        const Features& features, double h);

/// S33's figures of a run with features (Meshed::features).
struct FeatureReport {
  double angle = 0;
  std::size_t edges = 0, curves = 0, corners = 0;
  std::size_t corners_conformed = 0, curves_conformed = 0;
  double distance = -1;                       ///< with the statistics, in world units; -1 when not computed
  std::size_t splits = 0, splits_undone = 0;  ///< S35's splits kept, and undone (S35.4)
  std::size_t chord_splits = 0, chord_splits_refused = 0;  ///< S35.11's chord splits made, and refused
  std::size_t flips = 0;                                   ///< S35.9's flips kept
  std::size_t moves_undone = 0;                            ///< moves undone with them (S35.4)
  bool crease_cuts = false;                                ///< S35.7-S35.8 ran (--crease-cuts)
  std::size_t placed = 0;                                  ///< S35.8: vertices placed on the curves in candidate B
  std::size_t placed_kept = 0;                             ///< S35.8: vertices at a placed point in the mesh kept
};

/// S33's report of `features` conformed as `conformity` says (the distance
/// and S35.7-S35.8's figures left for the caller).
FeatureReport feature_report(const Features& features, const FeatureConformity& conformity);

}  // namespace bccmis::stuff
