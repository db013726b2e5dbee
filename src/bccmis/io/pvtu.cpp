#include "bccmis/io/pvtu.h"

#include <bit>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <utility>

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

namespace {

/// Passes the text written to it on to `out`, with `insert` called once
/// just before the first occurrence of `marker`: write_vtu's file streamed
/// with one more array, not held in memory.
class InsertBefore : public std::streambuf {
 public:
  InsertBefore(std::ostream& out, std::string marker, std::function<void(std::ostream&)> insert)
      : out_(out), marker_(std::move(marker)), insert_(std::move(insert)) {}
  bool inserted() const { return done_; }

 protected:
  int_type overflow(int_type c) override {
    if (c != traits_type::eof()) put(traits_type::to_char_type(c));
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    std::streamsize i = 0;
    for (; i < n && !done_; ++i) put(s[i]);
    if (i < n) out_.write(s + i, n - i);
    return n;
  }

 private:
  void put(char c) {
    if (done_) {
      out_.put(c);
      return;
    }
    held_ += c;
    while (!held_.empty() && marker_.compare(0, held_.size(), held_) != 0) {
      out_.put(held_[0]);
      held_.erase(0, 1);
    }
    if (held_ == marker_) {
      insert_(out_);
      out_ << held_;
      held_.clear();
      done_ = true;
    }
  }
  std::ostream& out_;
  std::string marker_;
  std::function<void(std::ostream&)> insert_;
  std::string held_;
  bool done_ = false;
};

}  // namespace

void write_vtu_piece(std::ostream& out, const d3::TetMeshF& mesh, std::span<const std::int64_t> global_id,
                     Encoding encoding) {
  static_assert(std::endian::native == std::endian::little, "the binary .vtu is written little-endian");
  if (global_id.size() != mesh.vertices.size()) throw std::logic_error("write_vtu_piece: not one global_id a vertex");
  // As write_vtu writes an array: a number a line, or base64 of a UInt64
  // byte count and the values, or the values compressed in blocks.
  const auto write_ids = [&](std::ostream& s) {
    s << "        <DataArray type=\"Int64\" Name=\"global_id\" format=\""
      << (encoding == Encoding::ascii ? "ascii" : "binary") << "\">\n";
    const std::string_view raw(reinterpret_cast<const char*>(global_id.data()), global_id.size_bytes());
    if (encoding == Encoding::ascii) {
      for (const std::int64_t id : global_id) s << id << '\n';
    } else if (encoding == Encoding::zlib) {
      s << "          " << detail::zlib_base64(raw) << '\n';
    } else {
      const std::uint64_t bytes = raw.size();
      s << "          ";
      detail::Base64Writer b64(s);
      b64.put(&bytes, sizeof bytes);
      b64.put(raw.data(), raw.size());
      b64.finish();
      s << '\n';
    }
    s << "        </DataArray>\n";
  };
  InsertBefore splice(out, "      </PointData>\n", write_ids);
  std::ostream through(&splice);
  write_vtu(through, mesh, encoding);
  through.flush();
  if (!splice.inserted()) throw std::logic_error("write_vtu_piece: write_vtu wrote no point data");
}

}  // namespace bccmis::io
