// The .vtu reader of tetrahedral meshes (vtu.h): the DataArrays found by
// their section and name, ASCII or base64 binary, raw or zlib-compressed.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "bccmis/io/detail/base64.h"
#include "bccmis/io/detail/zlib_blocks.h"
#include "bccmis/io/parse_error.h"
#include "bccmis/io/vtu.h"

namespace bccmis::io {

namespace {

class VtuText {
 public:
  VtuText(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  [[noreturn]] void fail(std::size_t at, const std::string& message) const {
    int line = 1, column = 1;
    for (std::size_t i = 0; i < at && i < text_.size(); ++i) text_[i] == '\n' ? (++line, column = 1) : ++column;
    throw ParseError(name_, line, column, message);
  }

  /// The value of attribute `key` in the tag starting at `tag` ("" if absent).
  std::string attribute(std::size_t tag, std::string_view key) const {
    const std::size_t end = text_.find('>', tag);
    const std::string_view t = text_.substr(tag, end == std::string_view::npos ? std::string_view::npos : end - tag);
    const std::string needle = " " + std::string(key) + "=\"";
    const std::size_t at = t.find(needle);
    if (at == std::string_view::npos) return "";
    const std::size_t from = at + needle.size();
    return std::string(t.substr(from, t.find('"', from) - from));
  }

  /// The DataArray named `array` (by Name, or the first) in the section
  /// `<section`, as doubles; fails when it is required and absent.
  std::vector<double> array(std::string_view section, std::string_view array, bool required) const {
    const std::size_t s = text_.find("<" + std::string(section));
    const std::size_t s_end = s == std::string_view::npos ? s : text_.find("</" + std::string(section), s);
    for (std::size_t at = s; at != std::string_view::npos && at < s_end;) {
      at = text_.find("<DataArray", at + 1);
      if (at == std::string_view::npos || at > s_end) break;
      if (!array.empty() && attribute(at, "Name") != array) continue;
      return values(at);
    }
    if (required)
      fail(s == std::string_view::npos ? 0 : s, "no DataArray '" + std::string(array) + "' in " + std::string(section));
    return {};
  }

 private:
  std::vector<double> values(std::size_t tag) const {
    const std::size_t open_end = text_.find('>', tag);
    const std::size_t close = text_.find("</DataArray>", open_end);
    if (open_end == std::string_view::npos || close == std::string_view::npos) fail(tag, "an unclosed DataArray");
    const std::string_view body = text_.substr(open_end + 1, close - open_end - 1);
    const std::string format = attribute(tag, "format"), type = attribute(tag, "type");
    std::vector<double> out;
    if (format == "ascii") {
      for (std::size_t i = 0; i < body.size();) {
        while (i < body.size() && std::strchr(" \t\r\n", body[i])) ++i;
        if (i == body.size()) break;
        double v = 0;
        const auto [end, ec] = std::from_chars(body.data() + i, body.data() + body.size(), v);
        if (ec != std::errc() || !std::isfinite(v)) fail(open_end + 1 + i, "expected a finite number");
        out.push_back(v);
        i = static_cast<std::size_t>(end - body.data());
      }
      return out;
    }
    if (format != "binary") fail(tag, "DataArray format '" + format + "': read ascii and binary (base64)");
    std::string bytes;
    if (!detail::from_base64(body, bytes)) fail(open_end + 1, "not base64");
    const std::size_t vtk_file = text_.find("<VTKFile");
    const std::size_t header = attribute(vtk_file, "header_type") == "UInt64" ? 8 : 4;
    std::uint64_t count = 0;
    const char* p = nullptr;
    if (!attribute(vtk_file, "compressor").empty()) {
      std::string why;
      auto raw = detail::zlib_inflate_blocks(bytes, header, why);
      if (!raw) fail(open_end + 1, why);
      bytes = std::move(*raw);
      count = bytes.size();
      p = bytes.data();
    } else {
      if (bytes.size() < header) fail(open_end + 1, "no byte count");
      std::memcpy(&count, bytes.data(), header);
      if (count > bytes.size() - header) fail(open_end + 1, "the byte count exceeds the data");
      p = bytes.data() + header;
    }
    const auto read = [&]<class T>(T) {
      if (count % sizeof(T) != 0) fail(open_end + 1, "the byte count is not a multiple of the type's size");
      for (std::size_t i = 0; i < count / sizeof(T); ++i) {
        T v;
        std::memcpy(&v, p + i * sizeof(T), sizeof(T));
        out.push_back(static_cast<double>(v));
      }
    };
    // VTK's type names and the C++ types they are.
    const bool known =
        (type == "UInt8" && (read(std::uint8_t{}), true)) || (type == "Int8" && (read(std::int8_t{}), true)) ||
        (type == "Int32" && (read(std::int32_t{}), true)) || (type == "UInt32" && (read(std::uint32_t{}), true)) ||
        (type == "Int64" && (read(std::int64_t{}), true)) || (type == "UInt64" && (read(std::uint64_t{}), true)) ||
        (type == "Float32" && (read(float{}), true)) || (type == "Float64" && (read(double{}), true));
    if (!known) fail(tag, "DataArray type '" + type + "'");
    for (const double v : out)
      if (!std::isfinite(v)) fail(open_end + 1, "a number that is not finite");
    return out;
  }

  std::string_view text_;
  const std::string& name_;
};

}  // namespace

d3::TetMeshF read_vtu(std::string_view text, const std::string& name, Orientation orientation) {
  const VtuText vtu(text, name);
  if (text.find("<VTKFile") == std::string_view::npos ||
      text.find("type=\"UnstructuredGrid\"") == std::string_view::npos)
    vtu.fail(0, "not a VTK UnstructuredGrid (.vtu) file");
  if (const std::string c = vtu.attribute(text.find("<VTKFile"), "compressor");
      !c.empty() && c != "vtkZLibDataCompressor")
    vtu.fail(text.find("<VTKFile"), "compressor '" + c + "': read uncompressed files and vtkZLibDataCompressor");
  const std::vector<double> xyz = vtu.array("Points", "", true);
  const std::vector<double> connectivity = vtu.array("Cells", "connectivity", true);
  const std::vector<double> offsets = vtu.array("Cells", "offsets", true);
  const std::vector<double> types = vtu.array("Cells", "types", true);
  const std::vector<double> kind = vtu.array("PointData", "kind", false);
  const std::vector<double> level = vtu.array("CellData", "level", false);
  const std::size_t cells_at = text.find("<Cells");
  if (xyz.size() % 3 != 0) vtu.fail(text.find("<Points"), "the points' coordinates are not triples");
  d3::TetMeshF mesh;
  for (std::size_t i = 0; i < xyz.size(); i += 3) mesh.vertices.push_back({xyz[i], xyz[i + 1], xyz[i + 2]});
  const std::size_t n = mesh.vertices.size();
  if (!kind.empty() && kind.size() != n) vtu.fail(text.find("<PointData"), "'kind' does not have one value a point");
  for (std::size_t i = 0; i < n; ++i) mesh.kind.push_back(kind.empty() ? 0 : static_cast<std::uint8_t>(kind[i]));
  if (offsets.size() != types.size() || (!level.empty() && level.size() != types.size()))
    vtu.fail(cells_at, "the cell arrays have different lengths");
  for (std::size_t c = 0; c < types.size(); ++c) {
    const std::string cell = "cell " + std::to_string(c);
    if (types[c] != 10)
      vtu.fail(cells_at, cell + " has VTK type " + std::to_string(types[c]) + ": read tetrahedra (10)");
    if (offsets[c] != 4.0 * static_cast<double>(c + 1) || offsets[c] > static_cast<double>(connectivity.size()))
      vtu.fail(cells_at, cell + ": offsets must be 4, 8, 12, ...");
    std::array<std::uint32_t, 4> t{};
    for (std::size_t k = 0; k < 4; ++k) {
      const double v = connectivity[4 * c + k];
      if (v < 0 || v >= static_cast<double>(n) || v != std::floor(v))
        vtu.fail(cells_at, cell + ": a point index out of range");
      t[k] = static_cast<std::uint32_t>(v);
      for (std::size_t j = 0; j < k; ++j)
        if (t[j] == t[k]) vtu.fail(cells_at, cell + ": point " + std::to_string(t[k]) + " appears twice");
    }
    if (const std::string why = orientation_fault(orientation, mesh.vertices, t); !why.empty())
      vtu.fail(cells_at, cell + why);
    mesh.tets.push_back(t);
    mesh.level.push_back(level.empty() ? 0 : static_cast<int>(level[c]));
  }
  return mesh;
}

}  // namespace bccmis::io
