// bccmis oracle utilities: semantic state diff, statistics, SVG pictures.
// Used by the CLI (tools/bccmis) and the conformance harness.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bccmis/d3/graph.h"
#include "bccmis/graph.h"

namespace bccmis {

/// The semantic difference of two states, by position: one line per
/// difference (lattice size, vertex only in A or only in B, vertex of another
/// kind, different level, different neighbor sets). Empty iff A == B.
std::vector<std::string> diff_states(const Graph& a, const Graph& b);
/// The same for two 3D states.
std::vector<std::string> diff_states(const d3::Graph& a, const d3::Graph& b);

/// Counts describing a state (the `bccmis stats` output).
struct Stats {
  std::map<int, std::size_t> cells_per_level;
  std::size_t cells = 0, nodes = 0, junctions = 0;
  std::size_t graph_edges = 0;      ///< stored node-center edges (each counted once)
  std::size_t hull_edges = 0;       ///< edges of eq. (1): sides of cells between consecutive boundary nodes
  std::size_t triangles = 0;        ///< one per (cell, hull edge) pair
  std::size_t reference_bytes = 0;  ///< estimate of the reference std::set/std::map storage
};
Stats stats(const Graph& g);

/// Stats as text, one `name value` line each (or JSON).
std::string format_stats(const Stats& s, bool json);

namespace d3 {
/// Counts describing a 3D state (`bccmis stats` on a 3D state or trace).
struct Stats {
  d3::LatticeSize size;
  std::map<int, std::size_t> cells_per_level;
  std::size_t cells = 0, nodes = 0;
  std::size_t junctions = 0;        ///< nodes with |N(n)| in {3, 5, 6, 7} (spec/lattice3d.md §3, F2)
  std::size_t graph_edges = 0;      ///< stored node-center edges (each counted once)
  std::size_t green_edges = 0;      ///< cube-edge segments between consecutive nodes, over all leaves
  std::size_t tetrahedra = 0;       ///< of the graded BCC mesh (spec/mesh3d.md)
  std::size_t hull_vertices = 0;    ///< mesh vertices in neither N nor C (domain-boundary face centers)
  std::size_t reference_bytes = 0;  ///< estimate of the reference std::set/std::map storage
};
}  // namespace d3
d3::Stats stats(const d3::Graph& g);
std::string format_stats(const d3::Stats& s, bool json);

/// The green edges of a 3D state (spec/mesh3d.md M12): over all leaves, the
/// segments between consecutive nodes of N(c) along each of the 12 edges of
/// c's cube, each once, as (smaller, larger) position pairs.
std::set<std::pair<d3::Point, d3::Point>> green_edges(const d3::Graph& g);

/// An SVG picture: cells shaded by level, graph edges (solid), hull edges of
/// eq. (1) (dashed), nodes (dots) and junctions (rings). `overlay`, SVG
/// elements in the picture's coordinates (760 px for the longer side of the
/// domain, a 20 px margin, y up), is drawn last, over everything.
std::string render_svg(const Graph& g, const std::string& title, std::string_view overlay = {});

/// An axis-aligned plane through a 3D lattice: coordinate `axis` (0 x, 1 y,
/// 2 z) equal to `value`.
struct SlicePlane {
  int axis = 2;
  std::int64_t value = 0;
};

/// The default slice of `bccmis render`: z at the middle of the box.
SlicePlane middle_slice(const d3::LatticeSize& size);

/// The leaves a slice cuts: those whose cube spans `slice.value` along the
/// axis, half-open [low, high), so that a plane through cube faces takes the
/// leaves above it (at the box's far face, the leaves below it). Each leaf
/// once, sorted.
std::vector<d3::Point> sliced_leaves(const d3::Graph& g, const SlicePlane& slice);

/// The 3D picture of `bccmis render` (spec/cli.md), one SVG of two panels.
/// Left: the domain box in a cabinet projection (x right, z up, y receding
/// up-right at half scale), showing its three visible faces y = 0, z = max
/// and x = max: the boundary triangles of the tetrahedral mesh on them
/// (triangles of exactly one tetrahedron, spec/mesh3d.md §6; polygons of
/// class "tri") filled by the level of their leaf and shaded per face, and
/// the green edges on them (class "green"); the slice plane's trace on those
/// faces is dashed. Right: the slice, the leaves it cuts as rectangles filled
/// by level (class "leaf"), their centers on the plane (class "center"), the
/// nodes on the plane as dots (class "node") and the junctions among them
/// (|N(n)| in {3, 5, 6, 7}) as rings (class "junction"). Throws
/// std::invalid_argument when the slice is not within the box.
namespace d3 {
std::string render_svg(const Graph& g, const std::string& title, const SlicePlane& slice);
}  // namespace d3

}  // namespace bccmis
