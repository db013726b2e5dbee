// Layer 2, structural (Erleben 2009, §2.1; derivations in spec/invariants.md).
//
// A cell's square is derived from its center's position alone (the level a
// position implies, Domain::center_level); layer 4 checks that the stored
// level agrees. A center whose position is not the center of any cell inside
// the domain cannot be judged here: it is skipped, and so is every node next
// to it, and layer 4 reports it (center-position / outside-domain).
//
// Centers first, in sorted order, each check in this order:
//   center-degree      4 <= |𝒩(c)| <= 8: ‖P‖ = 4 corners, ‖J‖ <= 4        §2.1
//   center-corner      𝒩(c) holds the 4 corners of c's square             §2.1
//   center-neighbor    every other element of 𝒩(c) is a side midpoint     §2.1
// then nodes, in sorted order:
//   node-degree        |𝒩(n)| <= 4, and, for a node that no cell lists as a
//                      side midpoint, exactly 1 (domain corner), 2 (boundary)
//                      or 4 (interior)                                     §1 ¶5
//   boundary-junction  no cell lists a midpoint of a side on the domain
//                      boundary (no finer cell can lie beyond it)          §2.1 eq. (6a)
//   junction-degree    a node listed as a side midpoint has exactly 3
//                      neighbors: that one coarse cell and two cells that
//                      have it as a corner                                 §2.1 ¶2
#include <optional>

#include "bccmis/invariants/detail/lattice_geometry.h"
#include "bccmis/invariants/detail/layers.h"

namespace bccmis::inv {

namespace {

std::string neighbors_text(std::size_t k) { return std::to_string(k) + (k == 1 ? " neighbor" : " neighbors"); }

}  // namespace

std::optional<Violation> check_structural(const Graph& g) {
  constexpr int layer = 2;
  const Domain domain(g.size);

  for (const Point& c : g.C) {
    const PointSet& nbrs = g.nbr(c);
    // center-degree: the paper's ‖P‖ = 4 and at most one junction per side.
    if (nbrs.size() < 4 || nbrs.size() > 8)
      return violation(layer, "center-degree", {c},
                       "center " + pos(c) + " has " + neighbors_text(nbrs.size()) +
                           "; a cell lists its 4 corners and at most 4 side midpoints (4..8)",
                       "§2.1");
    const std::optional<int> level = domain.center_level(c);
    if (!level) continue;  // not a cell center: layer 4
    const std::int64_t h = domain.half(*level);
    // center-corner: the four corners, in sorted order.
    for (const Point corner :
         {Point{c.x - h, c.y - h}, Point{c.x - h, c.y + h}, Point{c.x + h, c.y - h}, Point{c.x + h, c.y + h}})
      if (!nbrs.count(corner))
        return violation(layer, "center-corner", {c, corner},
                         "center " + pos(c) + " does not list " + pos(corner) + ", a corner of its level-" +
                             std::to_string(*level) + " cell " + square(c, h),
                         "§2.1");
    // center-neighbor: nothing but corners and side midpoints.
    for (const Point& n : nbrs)
      if (role_of(c, h, n) == Role::None)
        return violation(layer, "center-neighbor", {c, n},
                         "center " + pos(c) + " lists " + pos(n) +
                             ", which is neither a corner nor a side midpoint of its level-" + std::to_string(*level) +
                             " cell " + square(c, h),
                         "§2.1");
  }

  for (const Point& n : g.N) {
    const PointSet& nbrs = g.nbr(n);
    if (nbrs.size() > 4)
      return violation(layer, "node-degree", {n},
                       "node " + pos(n) + " has " + neighbors_text(nbrs.size()) +
                           "; a node has 1 to 4 (at most 4 cells meet at a point)",
                       "§1 ¶5");
    const Place place = domain.place(n);
    if (place == Place::Outside) continue;  // layer 4
    std::vector<Point> as_midpoint;         // cells that list n as a side midpoint
    std::size_t as_corner = 0;
    bool judged = true;
    for (const Point& c : nbrs) {
      const std::optional<int> level = domain.center_level(c);
      if (!level) {
        judged = false;  // a neighbor layer 4 will report
        break;
      }
      const Role r = role_of(c, domain.half(*level), n);
      if (r == Role::Midpoint) as_midpoint.push_back(c);
      if (r == Role::Corner) ++as_corner;
    }
    if (!judged) continue;

    if (!as_midpoint.empty()) {
      // A junction: the midpoint of a side of one coarse cell, with two finer
      // cells beyond that side having it as a corner.
      if (place != Place::Interior)
        return violation(layer, "boundary-junction", {as_midpoint.front(), n},
                         "center " + pos(as_midpoint.front()) + " lists " + pos(n) +
                             ", the midpoint of its side on the domain boundary; a side gets a junction only when "
                             "finer cells lie beyond it",
                         "§2.1 eq. (6a)");
      if (as_midpoint.size() > 1)
        return violation(layer, "junction-degree", {n, as_midpoint[0], as_midpoint[1]},
                         "junction " + pos(n) + " is a side midpoint of both " + pos(as_midpoint[0]) + " and " +
                             pos(as_midpoint[1]) + "; a junction lies on the side of exactly one coarser cell",
                         "§2.1 ¶2");
      if (nbrs.size() != 3)
        return violation(layer, "junction-degree", {n, as_midpoint.front()},
                         "junction " + pos(n) + " (a side midpoint of center " + pos(as_midpoint.front()) + ") has " +
                             neighbors_text(nbrs.size()) +
                             "; a junction has exactly 3: the coarse cell and the two finer cells beside it",
                         "§2.1 ¶2");
      continue;
    }
    // Every neighbor has n as a corner: the cells meeting at n fill all the
    // quadrants around n that lie in the domain.
    const std::size_t expected = place == Place::DomainCorner ? 1 : place == Place::Boundary ? 2 : 4;
    if (as_corner != expected) {
      const char* kind = place == Place::DomainCorner ? "domain corner"
                         : place == Place::Boundary   ? "boundary node"
                                                      : "interior node";
      std::string text = std::string(kind) + " " + pos(n) + " has " + neighbors_text(as_corner) + ", ";
      if (place == Place::Interior)
        text +=
            "none of which has it as a side midpoint; an interior corner has 4 (a junction 3, one of them the "
            "coarse cell that has it as a side midpoint)";
      else
        text += std::string("a ") + kind + " has " + std::to_string(expected);
      return violation(layer, "node-degree", {n}, text, "§1 ¶5");
    }
  }
  return std::nullopt;
}

}  // namespace bccmis::inv
