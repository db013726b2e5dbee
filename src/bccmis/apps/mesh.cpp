#include "bccmis/apps/mesh.h"

#include <charconv>
#include <map>
#include <system_error>

#include "bccmis/geometry.h"

namespace bccmis {

namespace {

// Shortest text that reads back as the same double.
void put(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void put(std::string& out, std::size_t v) { out += std::to_string(v); }

// Comment text on one line.
std::string one_line(std::string_view s) {
  std::string r(s);
  for (char& ch : r)
    if (ch == '\n' || ch == '\r') ch = ' ';
  return r;
}

}  // namespace

TriangleMesh triangulate(const Graph& g, const std::function<double(const Point&)>& height) {
  TriangleMesh m;
  const double S = static_cast<double>(level0_side(g.size));
  std::map<Point, std::size_t> index;
  auto add = [&](const Point& p) {
    index.emplace(p, m.vertices.size());
    m.vertices.push_back({static_cast<double>(p.x) / S, static_cast<double>(p.y) / S, height(p)});
    m.vertex_position.push_back(p);
  };
  for (const Point& n : g.N) add(n);
  for (const Point& c : g.C) add(c);
  for (const Point& c : g.C) {
    const std::vector<Point> ring = boundary_in_angular_order(g, c);
    const int level = g.level_of(c);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      m.triangles.push_back({index.at(c), index.at(ring[i]), index.at(ring[(i + 1) % ring.size()])});
      m.triangle_cell.push_back(c);
      m.triangle_level.push_back(level);
    }
  }
  return m;
}

std::string format_obj(const TriangleMesh& m, std::string_view comment) {
  std::string out = "# " + one_line(comment) + "\n# " + std::to_string(m.vertices.size()) + " vertices, " +
                    std::to_string(m.triangles.size()) + " triangles\n";
  for (const auto& v : m.vertices) {
    out += "v ";
    put(out, v[0]);
    out += ' ';
    put(out, v[1]);
    out += ' ';
    put(out, v[2]);
    out += '\n';
  }
  for (const auto& t : m.triangles) {
    out += "f ";
    put(out, t[0] + 1);
    out += ' ';
    put(out, t[1] + 1);
    out += ' ';
    put(out, t[2] + 1);
    out += '\n';
  }
  return out;
}

std::string format_ply(const TriangleMesh& m, std::string_view comment) {
  std::string out = "ply\nformat ascii 1.0\ncomment " + one_line(comment) + "\nelement vertex " +
                    std::to_string(m.vertices.size()) +
                    "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                    std::to_string(m.triangles.size()) +
                    "\nproperty list uchar int vertex_indices\nproperty int level\nend_header\n";
  for (const auto& v : m.vertices) {
    put(out, v[0]);
    out += ' ';
    put(out, v[1]);
    out += ' ';
    put(out, v[2]);
    out += '\n';
  }
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    const auto& t = m.triangles[i];
    out += "3 ";
    put(out, t[0]);
    out += ' ';
    put(out, t[1]);
    out += ' ';
    put(out, t[2]);
    out += ' ';
    out += std::to_string(m.triangle_level[i]);
    out += '\n';
  }
  return out;
}

std::string format_vtu(const TriangleMesh& m) {
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <UnstructuredGrid>\n"
      "    <Piece NumberOfPoints=\"" +
      std::to_string(m.vertices.size()) + "\" NumberOfCells=\"" + std::to_string(m.triangles.size()) + "\">\n";
  out += "      <PointData Scalars=\"height\">\n        <DataArray type=\"Float64\" Name=\"height\" format=\"ascii\">\n";
  for (const auto& v : m.vertices) {
    out += "          ";
    put(out, v[2]);
    out += '\n';
  }
  out += "        </DataArray>\n      </PointData>\n";
  out += "      <CellData Scalars=\"level\">\n        <DataArray type=\"Int32\" Name=\"level\" format=\"ascii\">\n";
  for (const int l : m.triangle_level) out += "          " + std::to_string(l) + "\n";
  out += "        </DataArray>\n";
  if (!m.triangle_error.empty()) {
    out += "        <DataArray type=\"Float64\" Name=\"error\" format=\"ascii\">\n";
    for (const double e : m.triangle_error) {
      out += "          ";
      put(out, e);
      out += '\n';
    }
    out += "        </DataArray>\n";
  }
  out += "      </CellData>\n";
  out += "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& v : m.vertices) {
    out += "          ";
    put(out, v[0]);
    out += ' ';
    put(out, v[1]);
    out += ' ';
    put(out, v[2]);
    out += '\n';
  }
  out += "        </DataArray>\n      </Points>\n";
  out += "      <Cells>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& t : m.triangles) {
    out += "          ";
    put(out, t[0]);
    out += ' ';
    put(out, t[1]);
    out += ' ';
    put(out, t[2]);
    out += '\n';
  }
  out += "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < m.triangles.size(); ++i) out += "          " + std::to_string(3 * (i + 1)) + "\n";
  out += "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < m.triangles.size(); ++i) out += "          5\n";
  out += "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

}  // namespace bccmis
