// The PLY reader (bccmis/io/ply.h, spec/formats.md "PLY input"): hand-made
// files, ASCII and binary built byte by byte here, each with the vertices,
// triangles and messages the spec gives it.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <string>

#include "bccmis/io/ply.h"
#include "bccmis/io/read_error.h"

namespace bccmis::io {
namespace {

/// What read_ply throws on `data`, or "" when it reads.
std::string message(const std::string& data) {
  try {
    read_ply("t.ply", data);
  } catch (const ReadError& e) {
    return e.what();
  }
  return "";
}

using Tri = std::array<std::uint32_t, 3>;

/// A binary body built value by value, in either byte order.
struct Bytes {
  bool little;
  std::string data;
  template <class T>
  Bytes& put(T value) {
    const auto b = std::bit_cast<std::array<unsigned char, sizeof(T)>>(value);  // the host's order
    const bool host_little = std::endian::native == std::endian::little;
    for (std::size_t i = 0; i < sizeof(T); ++i)
      data += static_cast<char>(b[host_little == little ? i : sizeof(T) - 1 - i]);
    return *this;
  }
};

constexpr const char* kSquareHeader =
    "element vertex 4\n"
    "property float x\n"
    "property float y\n"
    "property float z\n"
    "element face 1\n"
    "property list uchar int vertex_indices\n"
    "end_header\n";

TEST(PlyRead, AsciiSquareFannedWithCommentsAndObjInfo) {
  const auto s = read_ply("t.ply",
                          "ply\n"
                          "format ascii 1.0\n"
                          "comment made by hand\n"
                          "obj_info a square\n" +
                              std::string(kSquareHeader) +
                              "0 0 0\n"
                              "1 0 0\n"
                              "1 1 0.5\n"
                              "0 1 -2.25e1\n"
                              "4 0 1 2 3\n");
  ASSERT_EQ(s.vertices.size(), 4u);
  EXPECT_EQ(s.vertices[2], (d3::Vec3{1, 1, 0.5}));
  EXPECT_EQ(s.vertices[3], (d3::Vec3{0, 1, -22.5}));
  EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}}));  // the fan (v1, vi, vi+1)
  EXPECT_EQ(s.face, (std::vector<std::size_t>{0, 0}));
  EXPECT_EQ(s.line, (std::vector<std::size_t>{16, 16}));  // the face's line in the file
  EXPECT_EQ(s.vertex_base, 0u);
}

TEST(PlyRead, AsciiCrlfAndExtraPropertiesAndElementsSkipped) {
  // Normals and colours around the coordinates, a face flag and a texture
  // list around the indices, called vertex_index; an edge element with a list.
  const auto s = read_ply("t.ply",
                          "ply\r\nformat ascii 1.0\r\n"
                          "element vertex 3\r\n"
                          "property uchar red\r\nproperty double z\r\nproperty float nx\r\n"
                          "property int16 x\r\nproperty list uint8 float tex\r\nproperty uint y\r\n"
                          "element edge 1\r\nproperty list int int ends\r\n"
                          "element face 1\r\n"
                          "property uchar flags\r\nproperty list ushort uint32 vertex_index\r\n"
                          "property list uchar float texcoord\r\n"
                          "element material 1\r\nproperty float shine\r\n"
                          "end_header\r\n"
                          "255 3.5 0.1 -7 2 0.5 0.5 9\r\n"
                          "0 0 0\r\n0 0 0\r\n"  // one vertex on two lines: the tokens are what count
                          "0 1 0.5 0 0 1\r\n"
                          "2 0 1\r\n"
                          "1 3 2 0 1 6 0 0 1 0 1 1\r\n"
                          "0.5\r\n");
  ASSERT_EQ(s.vertices.size(), 3u);
  EXPECT_EQ(s.vertices[0], (d3::Vec3{-7, 9, 3.5}));
  EXPECT_EQ(s.vertices[1], (d3::Vec3{0, 0, 0}));
  EXPECT_EQ(s.vertices[2], (d3::Vec3{0, 1, 1}));
  EXPECT_EQ(s.triangles, (std::vector<Tri>{{2, 0, 1}}));
}

TEST(PlyRead, ElementWithoutPropertiesTakesNoRoomWhateverItsCount) {
  // Read past at once: looping over 10^18 instances of nothing would not end.
  const auto s =
      read_ply("t.ply", "ply\nformat binary_little_endian 1.0\nelement nothing 1000000000000000000\n" +
                            std::string(kSquareHeader) + std::string(4 * 12, '\0') + "\3" + std::string(3 * 4, '\0'));
  EXPECT_EQ(s.vertices.size(), 4u);
  EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 0, 0}}));
}

/// A square in binary of either byte order: coordinates of three types
/// around a colour, a triangle and a quad with a texture list after each.
std::string binary_square(bool little) {
  std::string head = std::string("ply\nformat ") + (little ? "binary_little_endian" : "binary_big_endian") +
                     " 1.0\n"
                     "element vertex 4\n"
                     "property double x\nproperty uchar red\nproperty float y\nproperty int16 z\n"
                     "element face 2\n"
                     "property list uint16 uint vertex_indices\n"
                     "property list uchar float tex\n"
                     "end_header\n";
  Bytes b{little, {}};
  b.put(0.0).put<std::uint8_t>(200).put(0.0f).put<std::int16_t>(-3);
  b.put(1.5).put<std::uint8_t>(200).put(0.0f).put<std::int16_t>(-3);
  b.put(1.5).put<std::uint8_t>(200).put(2.0f).put<std::int16_t>(-3);
  b.put(0.0).put<std::uint8_t>(200).put(2.0f).put<std::int16_t>(300);
  b.put<std::uint16_t>(3).put<std::uint32_t>(0).put<std::uint32_t>(1).put<std::uint32_t>(2);
  b.put<std::uint8_t>(1).put(0.25f);
  b.put<std::uint16_t>(4).put<std::uint32_t>(0).put<std::uint32_t>(2).put<std::uint32_t>(3).put<std::uint32_t>(1);
  b.put<std::uint8_t>(0);
  return head + b.data;
}

TEST(PlyRead, BinaryBothByteOrders) {
  for (const bool little : {true, false}) {
    SCOPED_TRACE(little ? "little-endian" : "big-endian");
    const auto s = read_ply("t.ply", binary_square(little));
    ASSERT_EQ(s.vertices.size(), 4u);
    EXPECT_EQ(s.vertices[0], (d3::Vec3{0, 0, -3}));
    EXPECT_EQ(s.vertices[2], (d3::Vec3{1.5, 2, -3}));
    EXPECT_EQ(s.vertices[3], (d3::Vec3{0, 2, 300}));
    EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}}));
    EXPECT_EQ(s.face, (std::vector<std::size_t>{0, 1, 1}));
    EXPECT_EQ(s.line, (std::vector<std::size_t>{0, 0, 0}));  // no lines in a binary body
  }
}

TEST(PlyRead, BinarySignedAndUnsignedEightBitTypes) {
  Bytes b{true, {}};
  b.put<std::int8_t>(-1).put<std::uint8_t>(255).put<std::int8_t>(-128);
  b.put<std::int8_t>(0).put<std::uint8_t>(0).put<std::int8_t>(0);
  b.put<std::int8_t>(1).put<std::uint8_t>(1).put<std::int8_t>(1);
  b.put<std::int8_t>(3).put<std::int8_t>(0).put<std::int8_t>(1).put<std::int8_t>(2);
  const auto s = read_ply("t.ply",
                          "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                          "property char x\nproperty uint8 y\nproperty int8 z\n"
                          "element face 1\nproperty list char char vertex_indices\nend_header\n" +
                              b.data);
  ASSERT_EQ(s.vertices.size(), 3u);
  EXPECT_EQ(s.vertices[0], (d3::Vec3{-1, 255, -128}));
  EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}}));
}

TEST(PlyRead, HeaderErrorsNameLineAndColumn) {
  EXPECT_EQ(message("plx\n"), "t.ply:1:1: expected 'ply' on the first line");
  EXPECT_EQ(message("ply\nformat binary_middle_endian 1.0\n"),
            "t.ply:2:8: unsupported format 'binary_middle_endian' (expected ascii, binary_little_endian or "
            "binary_big_endian)");
  EXPECT_EQ(message("ply\nformat ascii 2.0\n"), "t.ply:2:14: unsupported PLY version '2.0' (expected 1.0)");
  EXPECT_EQ(message("ply\nformat ascii 1.0\nelement vertex 3\n"),
            "t.ply:3:16: unexpected end of file in the header (expected 'end_header')");
  EXPECT_EQ(message("ply\nformat ascii 1.0\nelement vertex 1\nproperty list uchar float x\n"),
            "t.ply:4:27: vertex coordinate 'x' is a list");
  EXPECT_EQ(message("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                    "element face 0\nproperty list uchar int vertex_indices\nend_header\n"),
            "t.ply:8:1: element 'vertex' has no property 'z'");
  EXPECT_EQ(message("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty "
                    "float z\nelement face 0\nproperty int vertex_indices\n"),
            "t.ply:8:14: face property 'vertex_indices' is not a list");
  EXPECT_EQ(message("ply\nformat ascii 1.0\nelement vertex 1\nproperty half x\n"),
            "t.ply:4:10: unknown property type 'half' (expected char, uchar, short, ushort, int, uint, float, "
            "double, or int8 ... float64)");
  EXPECT_EQ(message("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                    "property float z\nend_header\n"),
            "t.ply:7:1: no element 'face' in the header (a point cloud is no surface)");
  EXPECT_EQ(message("ply\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n"),
            "t.ply:4:1: no 'format' line before 'end_header'");
}

TEST(PlyRead, AsciiBodyErrorsNameLineColumnAndElement) {
  const std::string head = "ply\nformat ascii 1.0\n" + std::string(kSquareHeader);  // the body starts on line 10
  const std::string vertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";                      // the face on line 14
  struct Case {
    std::string body, message;
  };
  for (const Case& c : {
           Case{"0 0 0\n1 0 0\n1 1 0\n0 1\n", "t.ply:13:4: unexpected end of file in vertex 3, property 'z'"},
           Case{"0 0 0\n1 0 0\n1 1 zero\n", "t.ply:12:5: bad number 'zero' (expected vertex 2, property 'z')"},
           Case{vertices + "4 0 1 2 4\n", "t.ply:14:9: face 0: vertex index 4 out of range (4 vertices)"},
           Case{vertices + "3 0 -1 2\n", "t.ply:14:5: face 0: vertex index -1 out of range (4 vertices)"},
           Case{vertices + "2 0 1\n", "t.ply:14:1: face 0 has 2 vertices (at least 3 needed)"},
           Case{vertices + "3 0 1 2\n\n7\n", "t.ply:16:1: unexpected text after the last element"},
       })
    EXPECT_EQ(message(head + c.body), c.message) << c.body;
}

TEST(PlyRead, BinaryBodyErrorsNameByteOffsetAndElement) {
  const std::string square = binary_square(true);
  const std::size_t body = square.find("end_header\n") + 11;
  // Vertex 3 starts at body + 3 * 15; its z at + 13.
  EXPECT_EQ(message(square.substr(0, body + 3 * 15 + 14)),
            "t.ply: byte " + std::to_string(body + 3 * 15 + 13) + ": binary PLY truncated in vertex 3, property 'z'");
  EXPECT_EQ(message(square + "xy"), "t.ply: byte " + std::to_string(square.size()) +
                                        ": 2 bytes after the last element (" + std::to_string(square.size()) +
                                        " bytes expected)");
  std::string bad_index = square;
  bad_index[body + 4 * 15 + 2 + 4] = 9;  // face 0's second index, little-endian: 1 -> 9
  EXPECT_EQ(message(bad_index),
            "t.ply: byte " + std::to_string(body + 4 * 15 + 6) + ": face 0: vertex index 9 out of range (4 vertices)");
  std::string nan = square;
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(std::numeric_limits<double>::quiet_NaN());
  for (int i = 0; i < 8; ++i) nan[body + 15 + i] = static_cast<char>(bits >> (8 * i));  // vertex 1's x
  EXPECT_EQ(message(nan),
            "t.ply: byte " + std::to_string(body + 15) + ": vertex 1, property 'x' is not a finite number");
}

}  // namespace
}  // namespace bccmis::io
