#include "bccmis/io/vtu.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string_view>

#include "bccmis/io/detail/point_text.h"
#include "bccmis/io/detail/triangle_text.h"
#include "bccmis/text_writer.h"

namespace bccmis::io {

using detail::kLine;
using detail::RecurringDoubles;
using detail::text_of;
using detail::write_double;
using detail::write_triangle;
using detail::write_xyz;

namespace {

template <class P>
void write_vtu_impl(std::ostream& out, const d3::BasicTetMesh<P>& mesh) {
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << mesh.vertices.size() << "\" NumberOfCells=\"" << mesh.tets.size() << "\">\n"
      << "      <PointData Scalars=\"kind\">\n"
      << "        <DataArray type=\"UInt8\" Name=\"kind\" format=\"ascii\">\n";
  for (const std::uint8_t k : mesh.kind) out << static_cast<int>(k) << '\n';
  out << "        </DataArray>\n"
      << "      </PointData>\n"
      << "      <CellData Scalars=\"level\">\n"
      << "        <DataArray type=\"Int32\" Name=\"level\" format=\"ascii\">\n";
  for (const int l : mesh.level) out << l << '\n';
  out << "        </DataArray>\n"
      << "      </CellData>\n"
      << "      <Points>\n"
      << "        <DataArray type=\"" << detail::coordinate_type<P>()
      << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const P& p : mesh.vertices) detail::write_point(out, p);
  out << "        </DataArray>\n"
      << "      </Points>\n"
      << "      <Cells>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& t : mesh.tets) out << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
  out << "        </DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < mesh.tets.size(); ++i) out << 4 * (i + 1) << '\n';
  out << "        </DataArray>\n"
      << "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < mesh.tets.size(); ++i) out << "10\n";
  out << "        </DataArray>\n"
      << "      </Cells>\n"
      << "    </Piece>\n"
      << "  </UnstructuredGrid>\n"
      << "</VTKFile>\n";
}

}  // namespace

void write_vtu(std::ostream& out, const d3::TetMesh& mesh) { write_vtu_impl(out, mesh); }
void write_vtu(std::ostream& out, const d3::TetMeshF& mesh) { write_vtu_impl(out, mesh); }

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

}  // namespace bccmis::io
