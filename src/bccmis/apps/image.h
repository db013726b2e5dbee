// bccmis apps: height-field images. A small PGM reader of our own (P2 and P5,
// 8- and 16-bit, any maxval, comments) and PNG through stb_image when the
// library was built with it (spec/apps.md, "Input images").
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace bccmis {

/// A gray image as heights: `values` is row-major, row 0 at the top (as
/// stored in the file), each sample divided by the file's maxval, so in [0, 1].
struct HeightField {
  std::int64_t width = 0;
  std::int64_t height = 0;
  std::vector<double> values;
  int maxval = 0;      ///< the file's maxval (255 or 65535 for PNG)
  std::string format;  ///< "P2", "P5" or "PNG"
  double at(std::int64_t col, std::int64_t row) const { return values[static_cast<std::size_t>(row * width + col)]; }
};

/// A malformed or unsupported image. what() names the file and where:
/// `file:line:column: message` in a PGM header or a P2 raster,
/// `file: byte N: message` in a P5 raster, `file: message` otherwise.
struct ImageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Limits that keep a hostile header from exhausting memory.
struct ImageLimits {
  std::int64_t max_side = 65536;                    ///< width and height at most this
  std::int64_t max_pixels = std::int64_t{1} << 26;  ///< width * height at most this (64 Mi)
};

/// Parses a PGM (P2 plain or P5 raw; maxval 1..65535, two bytes big-endian
/// per sample in P5 when maxval > 255; `#` comments in the header, and in a P2
/// raster). Samples above maxval, a truncated raster, a zero or too large
/// size and any other magic are errors. Bytes after a P5 raster are ignored
/// (netpbm allows several images in one file); after a P2 raster only
/// whitespace and comments may follow.
HeightField parse_pgm(std::string_view bytes, std::string_view file = "<pgm>", const ImageLimits& limits = {});

/// True when the library was built with stb_image (PNG input available).
bool png_supported();

/// Parses an 8- or 16-bit PNG through stb_image; colour is converted to
/// luminance by stb (Y = (77 R + 150 G + 29 B) / 256), alpha is dropped, no
/// gamma is applied. Throws ImageError when png_supported() is false.
HeightField parse_png(std::string_view bytes, std::string_view file = "<png>", const ImageLimits& limits = {});

/// PGM or PNG, chosen by the magic bytes; anything else is an ImageError.
HeightField parse_height_field(std::string_view bytes, std::string_view file, const ImageLimits& limits = {});

/// Reads and parses a file ("-" is not special here). Unreadable files are an
/// ImageError too.
HeightField read_height_field(const std::string& path, const ImageLimits& limits = {});

/// The field as a PGM with the given maxval (1..65535): P2 when `plain`,
/// otherwise P5. Values are rounded to the nearest level and clamped to [0, 1].
std::string format_pgm(const HeightField& f, int maxval, bool plain);

}  // namespace bccmis
