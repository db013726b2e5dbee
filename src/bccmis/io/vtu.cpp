#include "bccmis/io/vtu.h"

#include <algorithm>
#include <array>
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

/// One DataArray of `count` values of type T, the i-th `value_at(i)`
/// (per_line numbers a line in ASCII): ASCII text, base64 of a UInt64 byte
/// count followed by the little-endian values, streamed, or the values
/// compressed in blocks (detail/zlib_blocks.h).
template <class T, class ValueAt>
void write_data_array(std::ostream& out, const std::string& attributes, std::size_t count, const ValueAt& value_at,
                      std::size_t per_line, Encoding encoding) {
  out << "        <DataArray " << attributes << " format=\"" << (encoding == Encoding::ascii ? "ascii" : "binary")
      << "\">\n";
  if (encoding == Encoding::ascii) {
    for (std::size_t i = 0; i < count; ++i) {
      write_number(out, static_cast<T>(value_at(i)));
      out << ((i + 1) % per_line == 0 ? '\n' : ' ');
    }
  } else {
    static_assert(std::endian::native == std::endian::little, "the binary .vtu is written little-endian");
    // The values in chunks of 4,096, each handed to `sink` as bytes.
    const auto each_chunk = [&](const auto& sink) {
      std::array<T, 4096> chunk{};
      for (std::size_t i = 0; i < count;) {
        const std::size_t n = std::min(chunk.size(), count - i);
        for (std::size_t j = 0; j < n; ++j) chunk[j] = static_cast<T>(value_at(i + j));
        sink(chunk.data(), n * sizeof(T));
        i += n;
      }
    };
    const std::uint64_t bytes = count * sizeof(T);
    out << "          ";
    if (encoding == Encoding::zlib) {
      std::string raw;
      raw.reserve(bytes);
      each_chunk([&](const T* p, std::size_t n) { raw.append(reinterpret_cast<const char*>(p), n); });
      out << detail::zlib_base64(raw);
    } else {
      detail::Base64Writer b64(out);
      b64.put(&bytes, sizeof bytes);
      each_chunk([&](const T* p, std::size_t n) { b64.put(p, n); });
      b64.finish();
    }
    out << '\n';
  }
  out << "        </DataArray>\n";
}

template <class P>
void write_vtu_impl(std::ostream& out, const d3::BasicTetMesh<P>& mesh, Encoding encoding) {
  using Coordinate = std::conditional_t<std::is_same_v<P, d3::Point>, std::int64_t, double>;
  // Every array is read from the mesh as it is written: no copy of the mesh.
  const auto coordinate = [&](std::size_t i) -> Coordinate {
    const P& p = mesh.vertices[i / 3];
    if constexpr (std::is_same_v<P, d3::Point>)
      return i % 3 == 0 ? p.x : i % 3 == 1 ? p.y : p.z;
    else
      return p[i % 3];
  };
  const std::size_t nt = mesh.tets.size();
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\""
      << (encoding == Encoding::ascii ? "" : " header_type=\"UInt64\"")
      << (encoding == Encoding::zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") << ">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << mesh.vertices.size() << "\" NumberOfCells=\"" << nt << "\">\n"
      << "      <PointData Scalars=\"kind\">\n";
  write_data_array<std::uint8_t>(
      out, "type=\"UInt8\" Name=\"kind\"", mesh.kind.size(), [&](std::size_t i) { return mesh.kind[i]; }, 1, encoding);
  out << "      </PointData>\n"
      << "      <CellData Scalars=\"level\">\n";
  write_data_array<std::int32_t>(
      out, "type=\"Int32\" Name=\"level\"", mesh.level.size(), [&](std::size_t i) { return mesh.level[i]; }, 1,
      encoding);
  out << "      </CellData>\n"
      << "      <Points>\n";
  write_data_array<Coordinate>(out,
                               "type=\"" + std::string(detail::coordinate_type<P>()) + "\" NumberOfComponents=\"3\"",
                               3 * mesh.vertices.size(), coordinate, 3, encoding);
  out << "      </Points>\n"
      << "      <Cells>\n";
  write_data_array<std::int64_t>(
      out, "type=\"Int64\" Name=\"connectivity\"", 4 * nt, [&](std::size_t i) { return mesh.tets[i / 4][i % 4]; }, 4,
      encoding);
  write_data_array<std::int64_t>(
      out, "type=\"Int64\" Name=\"offsets\"", nt, [](std::size_t i) { return 4 * (i + 1); }, 1, encoding);
  write_data_array<std::uint8_t>(
      out, "type=\"UInt8\" Name=\"types\"", nt, [](std::size_t) { return 10; }, 1, encoding);
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
