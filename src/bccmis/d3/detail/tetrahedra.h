// bccmis::d3, internal: the rule of the graded BCC mesh (spec/mesh3d.md
// M1-M8) written once over every 3D lattice. A lattice is reached through the
// vocabulary of bccmis/lattice.h alone (cells, level_of, is_center, neighbors,
// size_of), so d3::tetrahedra (mesh.cpp, on Graph) and fast::tetrahedra
// (fast/d3/mesh.cpp, on d3::fast::Lattice) extract the same tetrahedra.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "bccmis/d3/geometry.h"
#include "bccmis/d3/mesh.h"
#include "bccmis/d3/point.h"

namespace bccmis::d3::detail {

inline std::int64_t& coord(Point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
inline std::int64_t coord(const Point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

inline std::int64_t extent(const LatticeSize& size, int axis) {
  const std::int64_t n = axis == 0 ? size.W : axis == 1 ? size.H : size.D;
  return n * level0_side(size);
}

/// The corners of face (axis, side) of the cube centred at u with half side
/// h, in cyclic order around the face.
inline std::array<Point, 4> face_corners(const Point& u, std::int64_t h, int axis, bool high) {
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  const std::int64_t da[4] = {-h, h, h, -h}, db[4] = {-h, -h, h, h};
  std::array<Point, 4> out{};
  for (std::size_t i = 0; i < 4; ++i) {
    Point p = u;
    coord(p, axis) += high ? h : -h;
    coord(p, a) += da[i];
    coord(p, b) += db[i];
    out[i] = p;
  }
  return out;
}

/// The nodes on leaf u's boundary as a set with contains(): N(u) by default;
/// a lattice may offer a cheaper view of the same set (d3::fast::Lattice reads
/// its slots), found by argument-dependent lookup.
template <class G>
decltype(auto) leaf_boundary(const G& g, const Point& u) {
  return neighbors(g, u);
}

/// The level of leaf u and M4.3's test (is w, across a face of u, a leaf?)
/// by the vocabulary; a lattice may answer both from what leaf_boundary
/// read (d3::fast::Lattice: spec/mesh3d.md M25), found by argument-dependent
/// lookup.
template <class G, class B>
int leaf_level(const G& g, const Point& u, const B&) {
  return level_of(g, u);
}
template <class G, class B>
bool equal_across(const G& g, const B&, int, bool, const Point& w) {
  return is_center(g, w);
}

/// spec/mesh3d.md M24: the 8 places of a face's boundary nodes in cyclic
/// order (even: the corners of face_corners, odd: the midpoint after each),
/// listed in the order of their positions, for a face whose normal is along
/// x or z (tangential coordinates compared a then b) and along y (b then a).
inline constexpr std::array<int, 8> kRingOrderXZ = {0, 7, 6, 1, 5, 2, 3, 4};
inline constexpr std::array<int, 8> kRingOrderY = {0, 1, 2, 7, 3, 6, 5, 4};

/// spec/mesh3d.md M1-M4 and M24, for one leaf: the tetrahedra of leaf u
/// (those with u as vertex 0; they depend on u's level, the nodes on u's
/// boundary and the centers across its faces), appended to out, positively
/// oriented and sorted, with no orientation test and no sort.
template <class G>
void leaf_tetrahedra(const G& g, const Point& u, std::vector<Tet>& out) {
  const LatticeSize& size = size_of(g);
  const auto& nu = leaf_boundary(g, u);
  const int l = leaf_level(g, u, nu);
  const std::int64_t s = cell_side(size, l), h = s / 2;
  struct Face {
    Point apex;
    int axis;
    bool high;
  };
  std::array<Face, 6> faces{};
  std::size_t count = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (const bool high : {false, true}) {
      // spec/mesh3d.md M4: f is the center point of face F.
      Point f = u;
      coord(f, axis) += high ? h : -h;
      Point apex;
      if (coord(f, axis) == 0 || coord(f, axis) == extent(size, axis)) {
        apex = f;  // M4.1, M8: a hull face
      } else if (nu.contains(f)) {
        apex = f;  // M4.2, M6: a split face, coarse side
      } else {
        Point w = u;
        coord(w, axis) += high ? s : -s;
        const bool equal = equal_across(g, nu, axis, high, w);
#ifndef NDEBUG
        // M4.3's look-up that M25 replaces, kept in debug builds.
        if (equal != is_center(g, w) || l != level_of(g, u))
          throw std::logic_error("tetrahedra: M25 reads a wrong equal face or level at " + to_string(u));
#endif
        if (equal) {
          if (w < u) continue;  // M3: an equal face is emitted once, from the smaller center
          apex = w;             // M4.3, M5: an equal face
        } else {
          // M4.4, M7: a split face, fine side; m is the coarse face's center.
          if (l == 0) throw std::logic_error("tetrahedra: no leaf across a face of level-0 cell " + to_string(u));
          Point m = f;
          for (int k = 0; k < 3; ++k)
            if (k != axis) coord(m, k) = coord(u, k) / (2 * s) * (2 * s) + s;
          if (!nu.contains(m))
            throw std::logic_error("tetrahedra: coarse face center " + to_string(m) + " is not a node of " +
                                   to_string(u));
          apex = m;
        }
      }
      faces[count++] = {apex, axis, high};
    }
  // spec/mesh3d.md M24: the faces' apexes differ, so the faces in the order
  // of their apexes give their tetrahedra in sorted order.
  for (std::size_t i = 1; i < count; ++i)
    for (std::size_t j = i; j > 0 && faces[j].apex < faces[j - 1].apex; --j) std::swap(faces[j], faces[j - 1]);
  for (std::size_t i = 0; i < count; ++i) {
    const auto [apex, axis, high] = faces[i];
    // The boundary nodes of F at their places: corners and the edge
    // midpoints that are nodes of N(u).
    const std::array<Point, 4> corners = face_corners(u, h, axis, high);
    std::array<Point, 8> ring{};
    std::array<bool, 8> present{};
    for (std::size_t k = 0; k < 4; ++k) {
      ring[2 * k] = corners[k];
      present[2 * k] = true;
      ring[2 * k + 1] = midpoint(corners[k], corners[(k + 1) % 4]);
      present[2 * k + 1] = nu.contains(ring[2 * k + 1]);
    }
    // spec/mesh3d.md M2, M24: one tetrahedron (u, apex, a, b) per segment ab
    // not through the apex, a the segment's end that comes first in the
    // cyclic order on a high face and second on a low one (then
    // det[apex - u, a - u, b - u] > 0, M3), taken in the order of a.
    for (const int j : axis == 1 ? kRingOrderY : kRingOrderXZ) {
      if (!present[static_cast<std::size_t>(j)]) continue;
      int k = j;
      do k = high ? (k + 1) % 8 : (k + 7) % 8;
      while (!present[static_cast<std::size_t>(k)]);
      const Point& a = ring[static_cast<std::size_t>(j)];
      const Point& b = ring[static_cast<std::size_t>(k)];
      // The apex of a fine side is a corner of the face (M7), so it is on
      // ab iff it is one of its ends.
      if (apex == a || apex == b) continue;
#ifndef NDEBUG
      // The exact test M24 replaces, kept in debug builds.
      if (orientation(u, apex, a, b) <= 0)
        throw std::logic_error("tetrahedra: M24 orients a tetrahedron of " + to_string(u) + " wrongly");
      if (!out.empty() && out.back()[0] == u && !(out.back() < Tet{u, apex, a, b}))
        throw std::logic_error("tetrahedra: M24 emits the tetrahedra of " + to_string(u) + " out of order");
#endif
      out.push_back({u, apex, a, b});
    }
  }
}

/// spec/mesh3d.md M1-M4: every tetrahedron of the graded mesh of g, each
/// once, positively oriented, sorted. Vertex 0 of a tetrahedron is the leaf
/// that made it and the leaves come in sorted order (cells(g) is sorted on
/// every lattice), so each leaf's tetrahedra in their order (M24) sort
/// them all.
template <class G>
std::vector<Tet> tetrahedra_of(const G& g) {
  std::vector<Tet> out;
  for (const Point& u : cells(g)) leaf_tetrahedra(g, u, out);
  return out;
}

}  // namespace bccmis::d3::detail
