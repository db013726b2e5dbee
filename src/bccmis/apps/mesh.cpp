#include "bccmis/apps/mesh.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "bccmis/fast/lattice.h"
#include "bccmis/geometry.h"
#include "bccmis/text_writer.h"

namespace bccmis {

namespace {

// The most bytes of the shortest round-trip text of a double (std::to_chars).
constexpr std::size_t kDoubleBytes = 32;

// Shortest text that reads back as the same double; returns its end.
char* write_double(char* p, double v) { return std::to_chars(p, p + kDoubleBytes, v).ptr; }

// write_double for values that recur: a mesh's x and y take few distinct
// values (multiples of the finest cell side), so the texts of recent values
// are kept in a small direct-mapped table and copied.
class RecurringDoubles {
 public:
  char* write(char* p, double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    Entry& e = entries_[(bits * 0x9E3779B97F4A7C15ull) >> (64 - kBits)];
    if (!e.used || e.bits != bits) {
      e.bits = bits;
      e.used = true;
      e.size = static_cast<std::size_t>(write_double(e.text, v) - e.text);
    }
    std::memcpy(p, e.text, kDoubleBytes);
    return p + e.size;
  }

 private:
  static constexpr int kBits = 12;
  struct Entry {
    std::uint64_t bits = 0;
    bool used = false;
    std::size_t size = 0;
    char text[kDoubleBytes] = {};
  };
  std::vector<Entry> entries_ = std::vector<Entry>(std::size_t{1} << kBits);
};

// Comment text on one line.
std::string one_line(std::string_view s) {
  std::string r(s);
  for (char& ch : r)
    if (ch == '\n' || ch == '\r') ch = ' ';
  return r;
}

// Room for a line of three doubles and a few more bytes.
constexpr std::size_t kLine = 3 * kDoubleBytes + 4 * TextWriter::kIntBytes + 32;

// "x y z" of a vertex (no newline).
char* write_xyz(char* p, RecurringDoubles& xy, const std::array<double, 3>& v) {
  p = xy.write(p, v[0]);
  *p++ = ' ';
  p = xy.write(p, v[1]);
  *p++ = ' ';
  return write_double(p, v[2]);
}

// "a b c" of a triangle, each index plus `base` (no newline).
char* write_triangle(char* p, const std::array<std::size_t, 3>& t, std::size_t base) {
  p = TextWriter::write_uint(p, t[0] + base);
  *p++ = ' ';
  p = TextWriter::write_uint(p, t[1] + base);
  *p++ = ' ';
  return TextWriter::write_uint(p, t[2] + base);
}

template <class Write>
std::string text_of(const Write& write) {
  std::ostringstream out;
  write(out);
  return std::move(out).str();
}

// The fan triangulation from the sorted nodes and cells: vertices are the
// nodes, then the centers; ring(c) is c's boundary in counter-clockwise
// order, level(c) its level.
template <class Nodes, class Cells, class Ring, class Level>
TriangleMesh triangulate_sorted(const LatticeSize& size, const Nodes& nodes, const Cells& cells, const Ring& ring,
                                const Level& level, const std::function<double(const Point&)>& height) {
  TriangleMesh m;
  const double S = static_cast<double>(level0_side(size));
  const std::size_t vertex_count = nodes.size() + cells.size();
  m.vertices.reserve(vertex_count);
  m.vertex_position.reserve(vertex_count);
  auto add = [&](const Point& p) {
    m.vertices.push_back({static_cast<double>(p.x) / S, static_cast<double>(p.y) / S, height(p)});
    m.vertex_position.push_back(p);
  };
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
  TriangleMesh m;
  const double S = static_cast<double>(level0_side(g.size()));
  const std::size_t vertex_count = node_slots.size() + cell_slots.size();
  m.vertices.reserve(vertex_count);
  m.vertex_position.reserve(vertex_count);
  auto add = [&](const Point& p) {
    m.vertices.push_back({static_cast<double>(p.x) / S, static_cast<double>(p.y) / S, height(p)});
    m.vertex_position.push_back(p);
  };
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

void write_obj(std::ostream& out, const TriangleMesh& m, std::string_view comment) {
  TextWriter w(out);
  w.put("# ");
  w.put(one_line(comment));
  w.put("\n# ");
  w.put_int(static_cast<std::int64_t>(m.vertices.size()));
  w.put(" vertices, ");
  w.put_int(static_cast<std::int64_t>(m.triangles.size()));
  w.put(" triangles\n");
  RecurringDoubles xy;
  for (const auto& v : m.vertices) {
    char* p = w.room(kLine);
    *p++ = 'v';
    *p++ = ' ';
    p = write_xyz(p, xy, v);
    *p++ = '\n';
    w.commit(p);
  }
  for (const auto& t : m.triangles) {
    char* p = w.room(kLine);
    *p++ = 'f';
    *p++ = ' ';
    p = write_triangle(p, t, 1);
    *p++ = '\n';
    w.commit(p);
  }
  w.flush();
}

std::string format_obj(const TriangleMesh& m, std::string_view comment) {
  return text_of([&](std::ostream& out) { write_obj(out, m, comment); });
}

void write_ply(std::ostream& out, const TriangleMesh& m, std::string_view comment) {
  TextWriter w(out);
  w.put("ply\nformat ascii 1.0\ncomment ");
  w.put(one_line(comment));
  w.put("\nelement vertex ");
  w.put_int(static_cast<std::int64_t>(m.vertices.size()));
  w.put("\nproperty double x\nproperty double y\nproperty double z\nelement face ");
  w.put_int(static_cast<std::int64_t>(m.triangles.size()));
  w.put("\nproperty list uchar int vertex_indices\nproperty int level\nend_header\n");
  RecurringDoubles xy;
  for (const auto& v : m.vertices) {
    char* p = w.room(kLine);
    p = write_xyz(p, xy, v);
    *p++ = '\n';
    w.commit(p);
  }
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    char* p = w.room(kLine);
    *p++ = '3';
    *p++ = ' ';
    p = write_triangle(p, m.triangles[i], 0);
    *p++ = ' ';
    p = TextWriter::write_int(p, m.triangle_level[i]);
    *p++ = '\n';
    w.commit(p);
  }
  w.flush();
}

std::string format_ply(const TriangleMesh& m, std::string_view comment) {
  return text_of([&](std::ostream& out) { write_ply(out, m, comment); });
}

void write_vtu(std::ostream& out, const TriangleMesh& m) {
  constexpr std::string_view indent = "          ";
  TextWriter w(out);
  w.put(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <UnstructuredGrid>\n"
      "    <Piece NumberOfPoints=\"");
  w.put_int(static_cast<std::int64_t>(m.vertices.size()));
  w.put("\" NumberOfCells=\"");
  w.put_int(static_cast<std::int64_t>(m.triangles.size()));
  w.put("\">\n");
  w.put(
      "      <PointData Scalars=\"height\">\n        <DataArray type=\"Float64\" Name=\"height\" format=\"ascii\">\n");
  // One number (or three) a line after the indent.
  auto line = [&](const auto& write) {
    char* p = w.room(kLine + indent.size());
    std::memcpy(p, indent.data(), indent.size());
    p = write(p + indent.size());
    *p++ = '\n';
    w.commit(p);
  };
  for (const auto& v : m.vertices) line([&](char* p) { return write_double(p, v[2]); });
  w.put("        </DataArray>\n      </PointData>\n");
  w.put("      <CellData Scalars=\"level\">\n        <DataArray type=\"Int32\" Name=\"level\" format=\"ascii\">\n");
  for (const int l : m.triangle_level) line([&](char* p) { return TextWriter::write_int(p, l); });
  w.put("        </DataArray>\n");
  if (!m.triangle_error.empty()) {
    w.put("        <DataArray type=\"Float64\" Name=\"error\" format=\"ascii\">\n");
    for (const double e : m.triangle_error) line([&](char* p) { return write_double(p, e); });
    w.put("        </DataArray>\n");
  }
  w.put("      </CellData>\n");
  w.put("      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  RecurringDoubles xy;
  for (const auto& v : m.vertices) line([&](char* p) { return write_xyz(p, xy, v); });
  w.put("        </DataArray>\n      </Points>\n");
  w.put("      <Cells>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for (const auto& t : m.triangles) line([&](char* p) { return write_triangle(p, t, 0); });
  w.put("        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for (std::size_t i = 0; i < m.triangles.size(); ++i)
    line([&](char* p) { return TextWriter::write_uint(p, 3 * (i + 1)); });
  w.put("        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (std::size_t i = 0; i < m.triangles.size(); ++i)
    line([](char* p) {
      *p = '5';
      return p + 1;
    });
  w.put("        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
  w.flush();
}

std::string format_vtu(const TriangleMesh& m) {
  return text_of([&](std::ostream& out) { write_vtu(out, m); });
}

}  // namespace bccmis
