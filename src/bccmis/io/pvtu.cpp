#include "bccmis/io/pvtu.h"

#include <bit>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "bccmis/io/detail/base64.h"
#include "bccmis/io/detail/zlib_blocks.h"
#include "bccmis/io/vtu.h"

namespace bccmis::io {

void write_pvtu(std::ostream& out, const std::vector<std::string>& pieces) {
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <PUnstructuredGrid GhostLevel=\"0\">\n"
      << "    <PPointData Scalars=\"kind\">\n      <PDataArray type=\"UInt8\" Name=\"kind\"/>\n"
      << "      <PDataArray type=\"Int64\" Name=\"global_id\"/>\n    </PPointData>\n"
      << "    <PCellData Scalars=\"level\">\n      <PDataArray type=\"Int32\" Name=\"level\"/>\n    </PCellData>\n"
      << "    <PPoints>\n      <PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n    </PPoints>\n";
  for (const std::string& piece : pieces) out << "    <Piece Source=\"" << piece << "\"/>\n";
  out << "  </PUnstructuredGrid>\n</VTKFile>\n";
}

void write_vtu_piece(std::ostream& out, const d3::TetMeshF& mesh, std::span<const std::int64_t> global_id,
                     Encoding encoding) {
  static_assert(std::endian::native == std::endian::little, "the binary .vtu is written little-endian");
  std::ostringstream whole;
  write_vtu(whole, mesh, encoding);
  const std::string text = std::move(whole).str();
  const std::string end = "      </PointData>\n";
  const std::size_t at = text.find(end);
  if (at == std::string::npos || global_id.size() != mesh.vertices.size())
    throw std::logic_error("write_vtu_piece: no point data to extend, or not one number a vertex");
  out << text.substr(0, at) << "        <DataArray type=\"Int64\" Name=\"global_id\" format=\""
      << (encoding == Encoding::ascii ? "ascii" : "binary") << "\">\n";
  // As write_vtu writes an array: a number a line, or base64 of a UInt64
  // byte count and the values, or the values compressed in blocks.
  const std::string_view raw(reinterpret_cast<const char*>(global_id.data()), global_id.size_bytes());
  if (encoding == Encoding::ascii) {
    for (const std::int64_t id : global_id) out << id << '\n';
  } else if (encoding == Encoding::zlib) {
    out << "          " << detail::zlib_base64(raw) << '\n';
  } else {
    const std::uint64_t bytes = raw.size();
    out << "          ";
    detail::Base64Writer b64(out);
    b64.put(&bytes, sizeof bytes);
    b64.put(raw.data(), raw.size());
    b64.finish();
    out << '\n';
  }
  out << "        </DataArray>\n" << text.substr(at);
}

}  // namespace bccmis::io
