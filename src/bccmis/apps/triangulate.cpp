#include "bccmis/apps/triangulate.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "bccmis/fast/lattice.h"
#include "bccmis/geometry.h"

namespace bccmis {

namespace {

// An empty mesh with room for `vertex_count` vertices.
TriangleMesh with_room_for(std::size_t vertex_count) {
  TriangleMesh m;
  m.vertices.reserve(vertex_count);
  m.vertex_position.reserve(vertex_count);
  return m;
}

// Appends the vertex of lattice position p: (x / S, y / S, height(p)), S the
// level-0 cell side.
void add_vertex(TriangleMesh& m, const Point& p, double S, const std::function<double(const Point&)>& height) {
  m.vertices.push_back({static_cast<double>(p.x) / S, static_cast<double>(p.y) / S, height(p)});
  m.vertex_position.push_back(p);
}

// The fan triangulation from the sorted nodes and cells: vertices are the
// nodes, then the centers; ring(c) is c's boundary in counter-clockwise
// order, level(c) its level.
template <class Nodes, class Cells, class Ring, class Level>
TriangleMesh triangulate_sorted(const LatticeSize& size, const Nodes& nodes, const Cells& cells, const Ring& ring,
                                const Level& level, const std::function<double(const Point&)>& height) {
  TriangleMesh m = with_room_for(nodes.size() + cells.size());
  const double S = static_cast<double>(level0_side(size));
  auto add = [&](const Point& p) { add_vertex(m, p, S, height); };
  for (const Point& n : nodes) add(n);
  for (const Point& c : cells) add(c);
  // The index of a node: its rank among the sorted nodes.
  auto node_index = [&](const Point& p) {
    const auto it = std::lower_bound(m.vertex_position.begin(), m.vertex_position.begin() + nodes.size(), p);
    if (it == m.vertex_position.begin() + nodes.size() || *it != p)
      throw std::out_of_range("triangulate: a neighbor of a cell is not a node");
    return static_cast<std::size_t>(it - m.vertex_position.begin());
  };
  std::size_t center_index = nodes.size();
  for (const Point& c : cells) {
    const std::vector<Point> r = ring(c);
    if (r.empty()) {
      ++center_index;
      continue;
    }
    const int l = level(c);
    const std::size_t first = node_index(r.front());
    std::size_t a = first;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const std::size_t b = i + 1 < r.size() ? node_index(r[i + 1]) : first;
      m.triangles.push_back({center_index, a, b});
      m.triangle_cell.push_back(c);
      m.triangle_level.push_back(l);
      a = b;
    }
    ++center_index;
  }
  return m;
}

}  // namespace

TriangleMesh triangulate(const Graph& g, const std::function<double(const Point&)>& height) {
  return triangulate_sorted(
      g.size, g.N, g.C, [&](const Point& c) { return boundary_in_angular_order(g, c); },
      [&](const Point& c) { return g.level_of(c); }, height);
}

TriangleMesh triangulate(const fast::Lattice& g, const std::function<double(const Point&)>& height) {
  // The same mesh as from the Graph, straight from the pools: a node's
  // vertex index is its rank among the sorted nodes, and a cell's ring is
  // read from its record in angular order.
  const std::vector<fast::Lattice::Index> node_slots = g.sorted_node_slots();
  const std::vector<fast::Lattice::Index> cell_slots = g.sorted_center_slots();
  TriangleMesh m = with_room_for(node_slots.size() + cell_slots.size());
  const double S = static_cast<double>(level0_side(g.size()));
  auto add = [&](const Point& p) { add_vertex(m, p, S, height); };
  std::vector<std::size_t> rank(g.node_pool().size());
  for (std::size_t i = 0; i < node_slots.size(); ++i) {
    rank[node_slots[i]] = i;
    add(g.node_position(node_slots[i]));
  }
  for (const fast::Lattice::Index c : cell_slots) add(g.center_pool()[c].position());
  m.triangles.reserve(4 * cell_slots.size());
  m.triangle_cell.reserve(4 * cell_slots.size());
  m.triangle_level.reserve(4 * cell_slots.size());
  std::size_t ring[8];
  for (std::size_t i = 0; i < cell_slots.size(); ++i) {
    const fast::Lattice::Index c = cell_slots[i];
    std::size_t k = 0;
    g.for_each_boundary_node(c, [&](fast::Lattice::Index n, const Point&) { ring[k++] = rank[n]; });
    const std::size_t center_index = node_slots.size() + i;
    const Point center = g.center_pool()[c].position();
    const int level = g.level(c);
    for (std::size_t j = 0; j < k; ++j) {
      m.triangles.push_back({center_index, ring[j], ring[(j + 1) % k]});
      m.triangle_cell.push_back(center);
      m.triangle_level.push_back(level);
    }
  }
  return m;
}

}  // namespace bccmis
