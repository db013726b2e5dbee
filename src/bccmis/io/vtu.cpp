#include "bccmis/io/vtu.h"

#include <bit>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "bccmis/io/detail/base64.h"
#include "bccmis/io/detail/point_text.h"
#include "bccmis/io/detail/triangle_text.h"
#include "bccmis/io/detail/zlib_blocks.h"
#include "bccmis/text_writer.h"

namespace bccmis::io {

using detail::kLine;
using detail::RecurringDoubles;
using detail::text_of;
using detail::write_double;
using detail::write_triangle;
using detail::write_xyz;

namespace {

/// The text of one number of a DataArray.
template <class T>
void write_number(std::ostream& out, T v) {
  char buf[32];
  if constexpr (sizeof(T) == 1)
    out << static_cast<int>(v);
  else
    out.write(buf, std::to_chars(buf, buf + sizeof buf, v).ptr - buf);
}

/// One DataArray of `values` (per_line numbers a line in ASCII): ASCII text,
/// base64 of a UInt64 byte count followed by the little-endian values, or
/// the values compressed in blocks (detail/zlib_blocks.h).
template <class T>
void write_data_array(std::ostream& out, const std::string& attributes, const std::vector<T>& values,
                      std::size_t per_line, Encoding encoding) {
  out << "        <DataArray " << attributes << " format=\"" << (encoding == Encoding::ascii ? "ascii" : "binary")
      << "\">\n";
  if (encoding == Encoding::ascii) {
    for (std::size_t i = 0; i < values.size(); ++i) {
      write_number(out, values[i]);
      out << ((i + 1) % per_line == 0 ? '\n' : ' ');
    }
  } else {
    static_assert(std::endian::native == std::endian::little, "the binary .vtu is written little-endian");
    const std::uint64_t bytes = values.size() * sizeof(T);
    std::string raw(sizeof bytes + bytes, '\0');
    std::memcpy(raw.data(), &bytes, sizeof bytes);
    if (bytes > 0) std::memcpy(raw.data() + sizeof bytes, values.data(), bytes);
    const std::string_view data = std::string_view(raw).substr(sizeof bytes);
    out << "          " << (encoding == Encoding::zlib ? detail::zlib_base64(data) : detail::base64(raw)) << '\n';
  }
  out << "        </DataArray>\n";
}

template <class P>
void write_vtu_impl(std::ostream& out, const d3::BasicTetMesh<P>& mesh, Encoding encoding) {
  using Coordinate = std::conditional_t<std::is_same_v<P, d3::Point>, std::int64_t, double>;
  std::vector<Coordinate> xyz;
  xyz.reserve(3 * mesh.vertices.size());
  for (const P& p : mesh.vertices) {
    if constexpr (std::is_same_v<P, d3::Point>)
      xyz.insert(xyz.end(), {p.x, p.y, p.z});
    else
      xyz.insert(xyz.end(), p.begin(), p.end());
  }
  std::vector<std::int64_t> connectivity, offsets;
  connectivity.reserve(4 * mesh.tets.size());
  offsets.reserve(mesh.tets.size());
  for (const auto& t : mesh.tets) {
    connectivity.insert(connectivity.end(), t.begin(), t.end());
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  }
  const std::vector<std::int32_t> level(mesh.level.begin(), mesh.level.end());
  const std::vector<std::uint8_t> types(mesh.tets.size(), 10);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\""
      << (encoding == Encoding::ascii ? "" : " header_type=\"UInt64\"")
      << (encoding == Encoding::zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") << ">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << mesh.vertices.size() << "\" NumberOfCells=\"" << mesh.tets.size() << "\">\n"
      << "      <PointData Scalars=\"kind\">\n";
  write_data_array(out, "type=\"UInt8\" Name=\"kind\"", mesh.kind, 1, encoding);
  out << "      </PointData>\n"
      << "      <CellData Scalars=\"level\">\n";
  write_data_array(out, "type=\"Int32\" Name=\"level\"", level, 1, encoding);
  out << "      </CellData>\n"
      << "      <Points>\n";
  write_data_array(out, "type=\"" + std::string(detail::coordinate_type<P>()) + "\" NumberOfComponents=\"3\"", xyz, 3,
                   encoding);
  out << "      </Points>\n"
      << "      <Cells>\n";
  write_data_array(out, "type=\"Int64\" Name=\"connectivity\"", connectivity, 4, encoding);
  write_data_array(out, "type=\"Int64\" Name=\"offsets\"", offsets, 1, encoding);
  write_data_array(out, "type=\"UInt8\" Name=\"types\"", types, 1, encoding);
  out << "      </Cells>\n"
      << "    </Piece>\n"
      << "  </UnstructuredGrid>\n"
      << "</VTKFile>\n";
}

}  // namespace

void write_vtu(std::ostream& out, const d3::TetMesh& mesh, Encoding encoding) { write_vtu_impl(out, mesh, encoding); }
void write_vtu(std::ostream& out, const d3::TetMeshF& mesh, Encoding encoding) { write_vtu_impl(out, mesh, encoding); }

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
