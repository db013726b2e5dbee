// 3D layer 2, structural (spec/lattice3d.md §3, F1-F3): every cell lists its
// 8 corners and otherwise only edge midpoints and face centers of its cube,
// and every node has the cardinality its role allows.
//
// A cell's cube comes from its center's position (the level the position
// implies), not from its stored level: layer 4 checks that the two agree. A
// center that is not the center of a cube inside the box is skipped here,
// with every node next to it (layer 4 reports it). Centers first, then nodes:
//   center-degree      8 <= |N(c)| <= 26                                   §3 F3
//   center-corner      N(c) holds the 8 corners of c's cube                §1
//   center-neighbor    the rest of N(c) are edge midpoints or face centers  §3 F3
//   face-center-edges  a listed face center comes with its 4 edge midpoints §3 F2
//   node-degree        |N(n)| <= 8; a pure node has exactly 2^k            §3 F1
//   boundary-junction  no listed face center on the domain boundary, no
//                      listed edge midpoint on a domain edge               §3 F2
//   junction-degree    a face center: 1 + 4; an edge midpoint: u + 2r with
//                      u + r = q (4 inside, 2 on a domain face), u, r >= 1  §3 F2
#include <optional>
#include <vector>

#include "bccmis/invariants/d3/detail/lattice_geometry.h"

namespace bccmis::d3::inv {

namespace {

const char* role_name(Role r) {
  switch (r) {
    case Role::Corner: return "a corner";
    case Role::EdgeMidpoint: return "an edge midpoint";
    case Role::FaceCenter: return "a face center";
    case Role::Other: break;
  }
  return "neither a corner, an edge midpoint nor a face center";
}

// How the cells of N(n) see a node.
struct NodeRoles {
  int corner = 0, edge = 0, face = 0;
  Point edge_holder{}, face_holder{};
  bool judged = true;  // false when some neighbour has no valid position
};

}  // namespace

std::optional<Violation> check_structural(const Graph& g) {
  constexpr int layer = 2;
  const Box box(g.size);

  // The cube of every center with a valid position: its half-side, or 0.
  auto half_of = [&](const Point& c) -> std::int64_t {
    const std::optional<int> l = box.center_level(c);
    return l ? box.half(*l) : 0;
  };
  auto role = [&](const Point& c, std::int64_t h, const Point& p) {
    return box.contains(p) ? role_on(c, h, p) : Role::Other;
  };
  auto cube = [&](const Point& c, std::int64_t h) { return "the cube " + cube_text(c, h) + " of center " + pos(c); };

  // center-degree
  for (const Point& c : g.C) {
    if (half_of(c) == 0) continue;
    const std::size_t k = g.nbr(c).size();
    if (k < 8 || k > 26)
      return violation(layer, "center-degree", {c},
                       "center " + pos(c) + " has " + std::to_string(k) + " nodes; a cell has 8 to 26 (8 corners, " +
                           "at most 12 edge midpoints and 6 face centers)",
                       "§3 F3");
  }

  // center-corner
  for (const Point& c : g.C) {
    const std::int64_t h = half_of(c);
    if (h == 0) continue;
    for (int i = 0; i < 8; ++i) {
      const Point p{c.x + ((i & 4) ? h : -h), c.y + ((i & 2) ? h : -h), c.z + ((i & 1) ? h : -h)};
      if (!g.nbr(c).count(p))
        return violation(layer, "center-corner", {c, p},
                         "center " + pos(c) + " does not list " + pos(p) + ", a corner of " + cube(c, h), "§1");
    }
  }

  // center-neighbor
  for (const Point& c : g.C) {
    const std::int64_t h = half_of(c);
    if (h == 0) continue;
    for (const Point& p : g.nbr(c))
      if (role(c, h, p) == Role::Other)
        return violation(layer, "center-neighbor", {c, p},
                         "center " + pos(c) + " lists " + pos(p) +
                             ", which is neither a corner, an edge midpoint nor a face center of " + cube(c, h),
                         "§3 F3");
  }

  // face-center-edges: the finer cells beyond a face have its edge midpoints
  // as corners, so they are nodes on c's boundary.
  for (const Point& c : g.C) {
    const std::int64_t h = half_of(c);
    if (h == 0) continue;
    for (const Point& f : g.nbr(c)) {
      if (role(c, h, f) != Role::FaceCenter) continue;
      for (int a = 0; a < 3; ++a) {
        if (coord(f, a) != coord(c, a)) continue;  // a runs along the face
        for (const std::int64_t d : {-h, h}) {
          const Point m{f.x + (a == 0 ? d : 0), f.y + (a == 1 ? d : 0), f.z + (a == 2 ? d : 0)};
          if (!g.nbr(c).count(m))
            return violation(layer, "face-center-edges", {c, f, m},
                             "center " + pos(c) + " lists the face center " + pos(f) + " but not the midpoint " +
                                 pos(m) + " of an edge of that face",
                             "§3 F2");
        }
      }
    }
  }

  // The role of every node in each of its cells.
  std::vector<NodeRoles> roles;
  roles.reserve(g.N.size());
  for (const Point& n : g.N) {
    NodeRoles r;
    for (const Point& c : g.nbr(n)) {
      const std::int64_t h = half_of(c);
      if (h == 0 || !box.contains(n)) {
        r.judged = false;
        break;
      }
      switch (role(c, h, n)) {
        case Role::Corner: ++r.corner; break;
        case Role::EdgeMidpoint:
          if (r.edge++ == 0) r.edge_holder = c;
          break;
        case Role::FaceCenter:
          if (r.face++ == 0) r.face_holder = c;
          break;
        case Role::Other: r.judged = false; break;  // not after center-neighbor with symmetry
      }
    }
    roles.push_back(r);
  }

  // node-degree: F1 for pure nodes, and the overall bound 8.
  {
    auto r = roles.begin();
    for (const Point& n : g.N) {
      const NodeRoles& k = *r++;
      if (!k.judged) continue;
      const std::size_t size = g.nbr(n).size();
      if (size > 8)
        return violation(layer, "node-degree", {n},
                         "node " + pos(n) + " has " + std::to_string(size) + " cells; a node has at most 8", "§3 F1");
      if (k.edge == 0 && k.face == 0) {
        const int inside = box.interior_coordinates(n);
        const std::size_t want = std::size_t{1} << inside;
        if (size != want)
          return violation(layer, "node-degree", {n},
                           "node " + pos(n) + " is a corner of each of its " + std::to_string(size) + " cells, but " +
                               std::to_string(inside) + " of its coordinates lie strictly inside the box, so a " +
                               "pure node there has exactly " + std::to_string(want),
                           "§3 F1");
      }
    }
  }

  // boundary-junction
  {
    auto r = roles.begin();
    for (const Point& n : g.N) {
      const NodeRoles& k = *r++;
      if (!k.judged) continue;
      const int inside = box.interior_coordinates(n);
      if (k.face > 0 && inside < 3)
        return violation(layer, "boundary-junction", {k.face_holder, n},
                         "center " + pos(k.face_holder) + " lists " + pos(n) + " as " + role_name(Role::FaceCenter) +
                             ", but it lies in the domain boundary, where no finer cell can be beyond the face",
                         "§3 F2");
      if (k.edge > 0 && inside < 2)
        return violation(layer, "boundary-junction", {k.edge_holder, n},
                         "center " + pos(k.edge_holder) + " lists " + pos(n) + " as " + role_name(Role::EdgeMidpoint) +
                             ", but it lies on a domain edge",
                         "§3 F2");
    }
  }

  // junction-degree
  {
    auto r = roles.begin();
    for (const Point& n : g.N) {
      const NodeRoles& k = *r++;
      if (!k.judged || (k.edge == 0 && k.face == 0)) continue;
      const Point holder = k.face > 0 ? k.face_holder : k.edge_holder;
      const std::string counts = "node " + pos(n) + " (" +
                                 role_name(k.face > 0 ? Role::FaceCenter : Role::EdgeMidpoint) + " of " + pos(holder) +
                                 ") is a face center of " + std::to_string(k.face) + " cells, an edge midpoint of " +
                                 std::to_string(k.edge) + " and a corner of " + std::to_string(k.corner);
      if (k.face > 0) {
        if (k.face != 1 || k.edge != 0 || k.corner != 4)
          return violation(
              layer, "junction-degree", {k.face_holder, n},
              counts +
                  "; a face center is a corner of exactly the 4 finer cells beyond it and of nothing else (|N| = 5)",
              "§3 F2");
        continue;
      }
      const int q = box.interior_coordinates(n) == 3 ? 4 : 2;  // quadrants around the edge inside the box
      const int refined = k.corner / 2;
      if (k.corner % 2 != 0 || refined < 1 || k.edge + refined != q)
        return violation(layer, "junction-degree", {k.edge_holder, n},
                         counts + "; an edge midpoint with " + std::to_string(q) +
                             " quadrants inside the box needs u >= 1 cells with it as an edge midpoint and 2r >= 2 " +
                             "with it as a corner, u + r = " + std::to_string(q) + " (|N| in {5, 6, 7} inside, 3 " +
                             "on a domain face)",
                         "§3 F2");
    }
  }
  return std::nullopt;
}

}  // namespace bccmis::d3::inv
