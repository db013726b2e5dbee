// The height-field readers (src/bccmis/apps/image.h): our PGM reader on P2/P5,
// 8/16-bit, odd maxvals and comments, its error messages, and PNG through
// stb_image on files written by a minimal encoder in this test.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/apps/image.h"

namespace bccmis {
namespace {

std::string error_of(std::string_view bytes, std::string_view file = "f.pgm", const ImageLimits& limits = {}) {
  try {
    parse_height_field(bytes, file, limits);
  } catch (const ImageError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Pgm, PlainEightBitWithComments) {
  const HeightField f = parse_pgm("P2 # a comment\n# another\n3 2\n# before maxval\n4\n0 1 2\n3 4 0 # trailing\n");
  EXPECT_EQ(f.format, "P2");
  EXPECT_EQ(f.width, 3);
  EXPECT_EQ(f.height, 2);
  EXPECT_EQ(f.maxval, 4);
  EXPECT_EQ(f.values, (std::vector<double>{0, 0.25, 0.5, 0.75, 1, 0}));
  EXPECT_DOUBLE_EQ(f.at(1, 1), 1.0);  // row 1 is the second text row
}

TEST(Pgm, RawEightAndSixteenBit) {
  std::string p5 = "P5\n2 2\n255\n";
  p5 += std::string("\x00\x80\xff\x01", 4);
  const HeightField a = parse_pgm(p5);
  EXPECT_EQ(a.format, "P5");
  EXPECT_EQ(a.values, (std::vector<double>{0, 128 / 255.0, 1, 1 / 255.0}));

  // 16-bit is big-endian: 0x0041 = 65 (stb_image 2.27 returns 16640 here).
  std::string p16 = "P5 2 1 65535\n";
  p16 += std::string("\x00\x41\xff\xff", 4);
  const HeightField b = parse_pgm(p16);
  EXPECT_EQ(b.maxval, 65535);
  EXPECT_DOUBLE_EQ(b.values[0], 65 / 65535.0);
  EXPECT_DOUBLE_EQ(b.values[1], 1.0);

  // Any maxval: 1000 needs two bytes per sample; 7 needs one.
  std::string odd = "P5\n# comment\n2 1\n1000\n";
  odd += std::string("\x03\xe8\x01\xf4", 4);
  EXPECT_EQ(parse_pgm(odd).values, (std::vector<double>{1.0, 0.5}));
  std::string seven = "P5 3 1 7\n";
  seven += std::string("\x00\x07\x03", 3);
  EXPECT_EQ(parse_pgm(seven).values, (std::vector<double>{0, 1, 3 / 7.0}));
}

TEST(Pgm, RoundTripThroughFormatPgm) {
  HeightField f;
  f.width = 3;
  f.height = 2;
  f.values = {0, 0.2, 0.4, 0.6, 0.8, 1.0};
  for (const int maxval : {5, 255, 1000, 65535})
    for (const bool plain : {true, false}) {
      const HeightField g = parse_pgm(format_pgm(f, maxval, plain));
      EXPECT_EQ(g.width, 3);
      EXPECT_EQ(g.maxval, maxval);
      for (std::size_t i = 0; i < f.values.size(); ++i) EXPECT_NEAR(g.values[i], f.values[i], 0.5 / maxval);
    }
}

TEST(Pgm, ErrorsNameTheFileAndThePlace) {
  // The input and the message, in the order the reader checks.
  const std::pair<std::string, std::string> cases[] = {
      {"", "f.pgm: empty file, expected a PGM or PNG image"},
      {"GIF89a", "f.pgm: not a PGM (P2/P5) or PNG image: it starts with 'G' 'I'"},
      {"P6\n1 1\n255\nabc",
       "f.pgm:1:1: wrong magic 'P6' (a colour PPM; convert it with ppmtopgm): expected P2 or P5 (a PGM image)"},
      {"P5\n0 4\n255\n", "f.pgm:2:1: zero width"},
      {"P2\n4 0\n255\n", "f.pgm:2:1: zero height"},
      {"P5\n# big\n100000 3\n255\n", "f.pgm:3:1: image of 100000x3 pixels exceeds the limit of 65536 pixels per side"},
      {"P5\n60000 60000\n255\n",
       "f.pgm:2:1: image of 60000x60000 = 3600000000 pixels exceeds the limit of 67108864 pixels"},
      {"P5\n99999999999999 2\n255\n", "f.pgm:2:1: the width is absurdly large"},
      {"P5\n2 2\n", "f.pgm:3:1: unexpected end of file, expected the maxval"},
      {"P5\n2 x\n255\n", "f.pgm:2:3: expected the height, found 'x'"},
      {"P5\n2 2\n70000\n", "f.pgm:3:1: maxval 70000 is out of range 1..65535"},
      {"P5\n2 2\n0\n", "f.pgm:3:1: maxval 0 is out of range 1..65535"},
      {std::string("P5\n2 2\n255\n\x01\x02\x03", 14),
       "f.pgm: byte 14: truncated raster: 2x2 samples of 1 byte need 4 bytes from byte 11, the file has 3"},
      {std::string("P5\n2 1\n65535\n\x01\x02\x03", 16),
       "f.pgm: byte 16: truncated raster: 2x1 samples of 2 bytes need 4 bytes from byte 13, the file has 3"},
      {std::string("P5\n2 1\n100\n\x01\xc8", 13), "f.pgm: byte 12: sample 200 exceeds maxval 100 (row 0, column 1)"},
      {"P2\n2 2\n10\n1 2\n3\n", "f.pgm:6:1: unexpected end of file: the raster has 3 of 4 samples (2x2)"},
      {"P2\n2 1\n10\n1 11\n", "f.pgm:4:3: sample 11 exceeds maxval 10 (row 0, column 1)"},
      {"P2\n2 1\n10\n1 2 3\n", "f.pgm:4:5: unexpected '3' after the 2 samples"},
      {"P2\n2 1\n10\n1 z\n", "f.pgm:4:3: expected a sample, found 'z'"},
      {"P2\n2 1\n10\n1 2z\n", "f.pgm:4:4: expected whitespace after a sample, found 'z'"},
  };
  for (const auto& [bytes, message] : cases) EXPECT_EQ(error_of(bytes), message);
  ImageLimits small;
  small.max_pixels = 10;
  EXPECT_EQ(error_of("P2 4 4 1\n", "f.pgm", small),
            "f.pgm:1:4: image of 4x4 = 16 pixels exceeds the limit of 10 pixels");
}

TEST(Pgm, UnreadableFileIsAnImageError) { EXPECT_THROW(read_height_field("/nonexistent/dir/x.pgm"), ImageError); }

// ---- PNG -------------------------------------------------------------------------

std::uint32_t crc32(const std::string& s) {
  std::uint32_t c = 0xffffffffu;
  for (const char ch : s) {
    c ^= static_cast<unsigned char>(ch);
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return ~c;
}

std::string be32(std::uint32_t v) {
  return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8), static_cast<char>(v)};
}

std::string chunk(const std::string& type, const std::string& data) {
  return be32(static_cast<std::uint32_t>(data.size())) + type + data + be32(crc32(type + data));
}

/// A PNG with stored (uncompressed) deflate blocks: `samples` are row-major,
/// `channels` per pixel (1 gray, 2 gray+alpha, 3 RGB), `bits` 8 or 16.
std::string make_png(int w, int h, int channels, int bits, const std::vector<unsigned>& samples) {
  const int colour_type = channels == 1 ? 0 : channels == 2 ? 4 : 2;
  std::string ihdr = be32(static_cast<std::uint32_t>(w)) + be32(static_cast<std::uint32_t>(h));
  ihdr += static_cast<char>(bits);
  ihdr += static_cast<char>(colour_type);
  ihdr += std::string(3, '\0');
  std::string raw;
  std::size_t k = 0;
  for (int y = 0; y < h; ++y) {
    raw += '\0';  // filter: none
    for (int x = 0; x < w * channels; ++x, ++k) {
      if (bits == 16) raw += static_cast<char>(samples[k] >> 8);
      raw += static_cast<char>(samples[k] & 0xff);
    }
  }
  std::string z = "\x78\x01";
  const auto len = static_cast<std::uint16_t>(raw.size());  // one stored block (small images only)
  z += '\x01';
  z += static_cast<char>(len & 0xff);
  z += static_cast<char>(len >> 8);
  z += static_cast<char>(~len & 0xff);
  z += static_cast<char>((~len >> 8) & 0xff);
  z += raw;
  std::uint32_t a = 1, b = 0;
  for (const char ch : raw) {
    a = (a + static_cast<unsigned char>(ch)) % 65521;
    b = (b + a) % 65521;
  }
  z += be32((b << 16) | a);
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", z) + chunk("IEND", "");
}

TEST(Png, GrayEightAndSixteenBitAndColourToLuminance) {
  if (!png_supported()) {
    EXPECT_NE(error_of(make_png(1, 1, 1, 8, {0}), "f.png").find("PNG input is not available"), std::string::npos);
    GTEST_SKIP() << "built without stb_image";
  }
  const HeightField g8 = parse_height_field(make_png(3, 2, 1, 8, {0, 51, 255, 1, 2, 3}), "g8.png");
  EXPECT_EQ(g8.format, "PNG");
  EXPECT_EQ(g8.maxval, 255);
  EXPECT_EQ(g8.width, 3);
  EXPECT_EQ(g8.height, 2);
  EXPECT_DOUBLE_EQ(g8.at(1, 0), 51 / 255.0);
  EXPECT_DOUBLE_EQ(g8.at(2, 1), 3 / 255.0);

  const HeightField g16 = parse_height_field(make_png(2, 1, 1, 16, {65, 40000}), "g16.png");
  EXPECT_EQ(g16.maxval, 65535);
  EXPECT_DOUBLE_EQ(g16.values[0], 65 / 65535.0);  // raw value, not byte-swapped
  EXPECT_DOUBLE_EQ(g16.values[1], 40000 / 65535.0);

  // RGB: stb's luminance (77 R + 150 G + 29 B) >> 8; gray+alpha drops alpha.
  const HeightField rgb = parse_height_field(make_png(2, 1, 3, 8, {255, 0, 0, 100, 100, 100}), "rgb.png");
  EXPECT_DOUBLE_EQ(rgb.values[0], ((77 * 255) >> 8) / 255.0);
  EXPECT_DOUBLE_EQ(rgb.values[1], 100 / 255.0);
  const HeightField ga = parse_height_field(make_png(1, 1, 2, 8, {200, 7}), "ga.png");
  EXPECT_DOUBLE_EQ(ga.values[0], 200 / 255.0);
}

TEST(Png, BrokenFilesAreImageErrors) {
  if (!png_supported()) GTEST_SKIP() << "built without stb_image";
  std::string png = make_png(4, 4, 1, 8, std::vector<unsigned>(16, 9));
  EXPECT_NE(error_of(png.substr(0, 30), "t.png").find("t.png: "), std::string::npos);
  EXPECT_NE(error_of(png.substr(0, 60), "t.png").find("t.png: "), std::string::npos);
  ImageLimits small;
  small.max_side = 3;
  EXPECT_EQ(error_of(png, "t.png", small), "t.png: image of 4x4 pixels exceeds the limit of 3 pixels per side");
}

TEST(Images, MutatedFilesParseOrFailCleanly) {
  // Flipped, dropped and inserted bytes: every result is a parse or an
  // ImageError (the sanitizer builds check that nothing else goes wrong).
  std::vector<std::string> seeds = {"P2\n# c\n3 2\n9\n0 1 2\n3 4 9\n",
                                    std::string("P5\n2 2\n300\n\x00\x01\x01\x2c\x00\x00\x00\x05", 20),
                                    std::string("P5 2 1 255\n\x07\x08", 13)};
  if (png_supported()) seeds.push_back(make_png(3, 3, 1, 16, {1, 2, 3, 4, 5, 6, 7, 8, 9}));
  std::uint64_t state = 12345;
  auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return state >> 33;
  };
  int parsed = 0, rejected = 0;
  for (const std::string& seed : seeds)
    for (int k = 0; k < 400; ++k) {
      std::string m = seed;
      for (int edits = 1 + static_cast<int>(next() % 3); edits > 0 && !m.empty(); --edits) {
        const std::size_t at = next() % m.size();
        switch (next() % 3) {
          case 0: m[at] = static_cast<char>(next()); break;
          case 1: m.erase(at, 1); break;
          default: m.insert(at, 1, static_cast<char>(next())); break;
        }
      }
      try {
        const HeightField f = parse_height_field(m, "m");
        EXPECT_EQ(f.values.size(), static_cast<std::size_t>(f.width * f.height));
        for (const double v : f.values) EXPECT_TRUE(v >= 0 && v <= 1);
        ++parsed;
      } catch (const ImageError&) {
        ++rejected;
      }
    }
  EXPECT_GT(parsed, 0);
  EXPECT_GT(rejected, 0);
}

}  // namespace
}  // namespace bccmis
