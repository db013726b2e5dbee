// Which surface format a file is in (bccmis/io/surface_format.h,
// spec/stuffing.md "Formats"): hand-made contents, each with the format the
// spec's rules give it and the words a message uses for it.
#include "bccmis/io/surface_format.h"

#include <gtest/gtest.h>

#include <string>

#include "bccmis/io/read_error.h"

namespace bccmis::io {
namespace {

/// A binary STL of `n` zero triangles whose 80-byte header starts with `head`.
std::string binary_stl(const std::string& head, unsigned n) {
  std::string data = head + std::string(80 - head.size(), ' ');
  data += static_cast<char>(n), data += std::string(3, '\0');
  return data + std::string(50 * n, '\0');
}

TEST(SurfaceFormat, ByExtensionCaseInsensitive) {
  EXPECT_EQ(format_of_extension("a/b.OFF"), SurfaceFormat::off);
  EXPECT_EQ(format_of_extension("b.obj"), SurfaceFormat::obj);
  EXPECT_EQ(format_of_extension("b.Stl"), SurfaceFormat::stl);
  EXPECT_EQ(format_of_extension("b.PLY"), SurfaceFormat::ply);
  EXPECT_EQ(format_of_extension("b.xyz"), std::nullopt);
  EXPECT_EQ(format_of_extension("dir.off/b"), std::nullopt);
  EXPECT_EQ(format_of_extension("-"), std::nullopt);
}

TEST(SurfaceFormat, SniffedByFirstWordOfText) {
  EXPECT_EQ(sniff_format("# a comment\n\nCOFF\n0 0 0\n"), SurfaceFormat::off);
  EXPECT_EQ(sniff_format("# exported\nmtllib a.mtl\nv 0 0 0\n"), SurfaceFormat::obj);
  EXPECT_EQ(sniff_format("  solid cube\nendsolid cube\n"), SurfaceFormat::stl);
  EXPECT_EQ(sniff_format("ply\nformat ascii 1.0\n"), SurfaceFormat::ply);
  EXPECT_EQ(sniff_format(std::string("ply\r\nformat binary_little_endian 1.0\r\nend_header\r\n") + '\0' + '\1'),
            SurfaceFormat::ply);  // binary: not text, still PLY by its first line
  EXPECT_EQ(sniff_format("plywood\n"), std::nullopt);
  EXPECT_EQ(sniff_format("OFFICE 1 2 3\n"), std::nullopt);  // a word that does not end in OFF
  EXPECT_EQ(sniff_format("hello\n"), std::nullopt);
  EXPECT_EQ(sniff_format(""), std::nullopt);
}

TEST(SurfaceFormat, BinaryStlBySizeEvenWithSolidHeader) {
  const std::string data = binary_stl("solid written by a binary exporter", 2);
  ASSERT_EQ(data.size(), 84u + 100u);
  EXPECT_EQ(sniff_format(data), SurfaceFormat::stl);
  EXPECT_EQ(describe_content(data), "binary STL");
  // One byte short: no plain format (binary, not text).
  EXPECT_EQ(sniff_format(data.substr(0, data.size() - 1)), std::nullopt);
  EXPECT_EQ(describe_content(data.substr(0, data.size() - 1)), "binary data");
}

TEST(SurfaceFormat, ContentInWords) {
  EXPECT_EQ(describe_content("OFF\n"), "OFF text");
  EXPECT_EQ(describe_content("v 1 2 3\n"), "OBJ text");
  EXPECT_EQ(describe_content("solid x\n"), "ASCII STL");
  EXPECT_EQ(describe_content("ply\nformat binary_big_endian 1.0\n"), "PLY");
  EXPECT_EQ(describe_content(""), "empty");
  EXPECT_EQ(describe_content("three vertices\n"), "text");
  EXPECT_FALSE(is_text(std::string("a\0b", 3)));
  EXPECT_TRUE(is_text("a\tb\r\n\f\v"));
}

/// What read_surface throws on `data` named `file` in `format`, or "" when it reads.
std::string refusal(const std::string& file, const std::string& data, std::optional<SurfaceFormat> format) {
  try {
    read_surface(file, data, format);
  } catch (const ReadError& e) {
    return e.what();
  }
  return "";
}

TEST(SurfaceFormat, ContentOfAnotherFormatIsRefusedNamingBoth) {
  EXPECT_EQ(refusal("t.stl", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", SurfaceFormat::stl),
            "t.stl: the content is OFF text, not STL (to read it as OFF: --format off)");
  EXPECT_EQ(refusal("t.off", "ply\nformat ascii 1.0\n", SurfaceFormat::off),
            "t.off: the content is PLY, not OFF (to read it as PLY: --format ply)");
  EXPECT_EQ(refusal("stdin", "three vertices\n", std::nullopt),
            "stdin: cannot tell the format of the content (text): expected OFF, OBJ, PLY or STL (--format off, "
            "obj, ply or stl says which)");
}

TEST(SurfaceFormat, SniffedContentIsRead) {
  const TriangleSoup s = read_surface("stdin", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", std::nullopt);
  EXPECT_EQ(s.vertices.size(), 3u);
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.vertex_base, 1u);  // read as OBJ
}

}  // namespace
}  // namespace bccmis::io
