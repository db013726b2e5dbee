// The zlib-compressed .vtu (spec/mesh3d.md M20; bccmis/io/vtu.h): the
// block header written on the block-size line, read back, and VTK's other
// header conventions (a last block of size 0 is full; UInt32 headers) read
// from files built here with zlib directly.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "bccmis/io/detail/base64.h"
#include "bccmis/io/parse_error.h"
#include "bccmis/io/vtu.h"

namespace bccmis::io {
namespace {

int sign(const d3::Vec3& a, const d3::Vec3& b, const d3::Vec3& c, const d3::Vec3& d) {
  const auto m = [](const d3::Vec3& p, const d3::Vec3& q) { return d3::Vec3{q[0] - p[0], q[1] - p[1], q[2] - p[2]}; };
  const d3::Vec3 u = m(a, b), v = m(a, c), w = m(a, d);
  const double det =
      u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
  return (det > 0) - (det < 0);
}

/// The body (the text between the tags) of the DataArray that follows `after`.
std::string body_after(const std::string& text, const std::string& after) {
  const std::size_t open = text.find('>', text.find("<DataArray", text.find(after))) + 1;
  return text.substr(open, text.find("</DataArray>", open) - open);
}

/// n points on a line and one tetrahedron on the first four.
d3::TetMeshF points_mesh(std::size_t n) {
  d3::TetMeshF m;
  for (std::size_t i = 0; i < n; ++i) m.vertices.push_back({double(i), double(i % 7), double(i % 5)});
  m.vertices[0] = {0, 0, 0}, m.vertices[1] = {1, 0, 0}, m.vertices[2] = {0, 1, 0}, m.vertices[3] = {0, 0, 1};
  m.kind.assign(n, 1);
  m.tets = {{0, 1, 2, 3}};
  m.level = {2};
  return m;
}

TEST(VtuCompressed, BlocksEndExactlyOnTheBlockSize) {
  // 4096 points: the coordinates are 98,304 bytes, three full blocks of
  // 32,768; 4097 points: three full blocks and a last one of 24 bytes.
  for (const std::size_t n : {std::size_t{4096}, std::size_t{4097}}) {
    const d3::TetMeshF mesh = points_mesh(n);
    std::ostringstream out;
    write_vtu(out, mesh, Encoding::zlib);
    const std::string text = out.str();
    ASSERT_NE(text.find("header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\""), std::string::npos);
    std::string bytes;
    ASSERT_TRUE(detail::from_base64(body_after(text, "<Points"), bytes));
    std::uint64_t header[4];
    std::memcpy(header, bytes.data(), sizeof header);
    const std::uint64_t blocks = n == 4096 ? 3 : 4;
    EXPECT_EQ(header[0], blocks);
    EXPECT_EQ(header[1], 32768u);
    EXPECT_EQ(header[2], n == 4096 ? 32768u : 24u);
    // The blocks inflate, one by one, to the coordinates.
    std::vector<double> raw(3 * n);
    std::size_t at = (3 + blocks) * 8, into = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      std::uint64_t compressed = 0;
      std::memcpy(&compressed, bytes.data() + (3 + b) * 8, 8);
      uLongf size = static_cast<uLongf>(raw.size() * 8 - into);
      ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(raw.data()) + into, &size,
                           reinterpret_cast<const Bytef*>(bytes.data() + at), static_cast<uLong>(compressed)),
                Z_OK);
      into += size, at += compressed;
    }
    EXPECT_EQ(into, 24 * n);
    EXPECT_EQ(at, bytes.size());
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) ASSERT_EQ(raw[3 * i + k], mesh.vertices[i][k]) << "point " << i;
    const d3::TetMeshF back = read_vtu(text, "z.vtu", sign);
    EXPECT_EQ(back.vertices, mesh.vertices);
    EXPECT_EQ(back.tets, mesh.tets);
    EXPECT_EQ(back.kind, mesh.kind);
    EXPECT_EQ(back.level, mesh.level);
  }
}

/// A compressed DataArray of `values` in one block, its header of `Int`s
/// saying the last block's size is `last`.
template <class Int, class T>
std::string hand_compressed(const std::vector<T>& values, Int last) {
  const std::size_t size = values.size() * sizeof(T);
  std::vector<Bytef> z(compressBound(size));
  uLongf zsize = static_cast<uLongf>(z.size());
  EXPECT_EQ(compress(z.data(), &zsize, reinterpret_cast<const Bytef*>(values.data()), size), Z_OK);
  const Int header[4] = {1, static_cast<Int>(size), last, static_cast<Int>(zsize)};
  return detail::base64(std::string(reinterpret_cast<const char*>(header), sizeof header)) +
         detail::base64(std::string(reinterpret_cast<const char*>(z.data()), zsize));
}

template <class Int>
std::string hand_vtu(Int last_block) {
  const std::string type = sizeof(Int) == 8 ? "UInt64" : "UInt32";
  const auto array = [&](const std::string& attributes, const std::string& data) {
    return "<DataArray " + attributes + " format=\"binary\">" + data + "</DataArray>\n";
  };
  return "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"" + type +
         "\" compressor=\"vtkZLibDataCompressor\">\n<UnstructuredGrid><Piece NumberOfPoints=\"4\" "
         "NumberOfCells=\"1\">\n<Points>" +
         array("type=\"Float32\" NumberOfComponents=\"3\"",
               hand_compressed<Int>(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, last_block)) +
         "</Points>\n<Cells>" +
         array("type=\"Int32\" Name=\"connectivity\"", hand_compressed<Int>(std::vector<std::int32_t>{0, 1, 2, 3}, 0)) +
         array("type=\"Int32\" Name=\"offsets\"", hand_compressed<Int>(std::vector<std::int32_t>{4}, 0)) +
         array("type=\"UInt8\" Name=\"types\"", hand_compressed<Int>(std::vector<std::uint8_t>{10}, 0)) +
         "</Cells>\n</Piece></UnstructuredGrid></VTKFile>\n";
}

TEST(VtuCompressed, ReadsVtkHeaderConventions) {
  const std::vector<d3::Vec3> want = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  // A last block of size 0 is a full block, with UInt64 and UInt32 headers.
  EXPECT_EQ(read_vtu(hand_vtu<std::uint64_t>(0), "a.vtu", sign).vertices, want);
  EXPECT_EQ(read_vtu(hand_vtu<std::uint32_t>(0), "b.vtu", sign).vertices, want);
  // ... and the last block's size written out (48 bytes of Float32 coordinates).
  EXPECT_EQ(read_vtu(hand_vtu<std::uint32_t>(48), "c.vtu", sign).tets,
            (std::vector<std::array<std::uint32_t, 4>>{{0, 1, 2, 3}}));
  // One byte more than the block holds: it does not inflate to that size.
  try {
    read_vtu(hand_vtu<std::uint32_t>(49), "d.vtu", sign);
    FAIL() << "a last block of 49 bytes was read";
  } catch (const ParseError& e) {
    // Line 3 holds <Points><DataArray ...>: the body starts at column 74.
    EXPECT_STREQ(e.what(), "d.vtu:3:74: compressed block 0 does not inflate to 49 bytes");
  }
  // A last block promising 8 GiB from a few dozen compressed bytes:
  // refused by deflate's largest ratio (about 1032 to 1), before any
  // allocation, as the block that cannot inflate to its size that it is.
  try {
    read_vtu(hand_vtu<std::uint64_t>(std::uint64_t{1} << 33), "e.vtu", sign);
    FAIL() << "a last block of 8 GiB was read";
  } catch (const ParseError& e) {
    EXPECT_STREQ(e.what(), "e.vtu:3:74: compressed block 0 does not inflate to 8589934592 bytes");
  }
}

}  // namespace
}  // namespace bccmis::io
