// bccmis::d3, internal: the rule of the graded BCC mesh (spec/mesh3d.md
// M1-M8) written once over every 3D lattice. A lattice is reached through the
// vocabulary of bccmis/lattice.h alone (cells, level_of, is_center, neighbors,
// size_of), so d3::tetrahedra (mesh.cpp, on Graph) and fast::tetrahedra
// (fast/d3/mesh.cpp, on d3::fast::Lattice) extract the same tetrahedra.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
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

/// spec/mesh3d.md M1-M4, for one leaf: the tetrahedra of leaf u (those with
/// u as vertex 0; they depend on u's level, the nodes on u's boundary and the
/// centers across its faces), appended to out, sorted; `ring` is scratch.
template <class G>
void leaf_tetrahedra(const G& g, const Point& u, std::vector<Tet>& out, std::vector<Point>& ring) {
  const LatticeSize& size = size_of(g);
  const std::size_t first = out.size();
  const int l = level_of(g, u);
  const std::int64_t s = cell_side(size, l), h = s / 2;
  const auto& nu = leaf_boundary(g, u);
  for (int axis = 0; axis < 3; ++axis)
    for (const bool high : {false, true}) {
      // spec/mesh3d.md M4: f is the center point of face F.
      Point f = u;
      coord(f, axis) += high ? h : -h;
      Point apex;
      bool emit = true;
      if (coord(f, axis) == 0 || coord(f, axis) == extent(size, axis)) {
        apex = f;  // M4.1, M8: a hull face
      } else if (nu.contains(f)) {
        apex = f;  // M4.2, M6: a split face, coarse side
      } else {
        Point w = u;
        coord(w, axis) += high ? s : -s;
        if (is_center(g, w)) {
          apex = w;      // M4.3, M5: an equal face
          emit = u < w;  // M3: emitted once, from the smaller center
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
      if (!emit) continue;
      // The boundary nodes of F in cyclic order: corners and the edge
      // midpoints that are nodes of N(u).
      const std::array<Point, 4> corners = face_corners(u, h, axis, high);
      ring.clear();
      for (std::size_t i = 0; i < 4; ++i) {
        ring.push_back(corners[i]);
        const Point e = midpoint(corners[i], corners[(i + 1) % 4]);
        if (nu.contains(e)) ring.push_back(e);
      }
      // spec/mesh3d.md M2: one tetrahedron per segment ab not through the
      // apex. The apex of a fine side is a corner of the face (M7), so it
      // is on ab iff it is one of its ends.
      for (std::size_t i = 0; i < ring.size(); ++i) {
        Point a = ring[i], b = ring[(i + 1) % ring.size()];
        if (apex == a || apex == b) continue;
        const int o = orientation(u, apex, a, b);
        if (o == 0) throw std::logic_error("tetrahedra: degenerate tetrahedron at " + to_string(u));
        if (o < 0) std::swap(a, b);  // M3
        out.push_back({u, apex, a, b});
      }
    }
  const auto from = out.begin() + static_cast<std::ptrdiff_t>(first);
  std::sort(from, out.end());
  out.erase(std::unique(from, out.end()), out.end());
}

/// spec/mesh3d.md M1-M4: every tetrahedron of the graded mesh of g, each
/// once, positively oriented, sorted. Vertex 0 of a tetrahedron is the leaf
/// that made it and the leaves come in sorted order (cells(g) is sorted on
/// every lattice), so sorting each leaf's tetrahedra sorts them all.
template <class G>
std::vector<Tet> tetrahedra_of(const G& g) {
  std::vector<Tet> out;
  std::vector<Point> ring;
  ring.reserve(8);
  for (const Point& u : cells(g)) leaf_tetrahedra(g, u, out, ring);
  return out;
}

}  // namespace bccmis::d3::detail
