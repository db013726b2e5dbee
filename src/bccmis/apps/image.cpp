#include "bccmis/apps/image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>

#if BCCMIS_APPS_HAVE_STB
#include <stb_image.h>
#endif

namespace bccmis {

namespace {

std::string hex_byte(unsigned char b) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02x", static_cast<unsigned>(b));
  return buf;
}

// A printable rendering of the byte at hand, for "found ..." messages.
std::string describe(std::string_view bytes, std::size_t pos) {
  if (pos >= bytes.size()) return "end of file";
  const auto b = static_cast<unsigned char>(bytes[pos]);
  std::string r;
  if (b >= 0x21 && b < 0x7f) {
    r += '\'';
    r += static_cast<char>(b);
    r += '\'';
  } else {
    r += "byte ";
    r += hex_byte(b);
  }
  return r;
}

void check_size(std::int64_t w, std::int64_t h, const ImageLimits& limits, const std::string& where) {
  if (w <= 0) throw ImageError(where + "zero width");
  if (h <= 0) throw ImageError(where + "zero height");
  if (w > limits.max_side || h > limits.max_side)
    throw ImageError(where + "image of " + std::to_string(w) + "x" + std::to_string(h) +
                     " pixels exceeds the limit of " + std::to_string(limits.max_side) + " pixels per side");
  if (w * h > limits.max_pixels)
    throw ImageError(where + "image of " + std::to_string(w) + "x" + std::to_string(h) + " = " + std::to_string(w * h) +
                     " pixels exceeds the limit of " + std::to_string(limits.max_pixels) + " pixels");
}

// A cursor over a PGM file that knows its line and column (1-based).
class Cursor {
 public:
  Cursor(std::string_view bytes, std::string_view file) : bytes_(bytes), file_(file) {}

  bool at_end() const { return pos_ >= bytes_.size(); }
  std::size_t pos() const { return pos_; }
  unsigned char peek() const { return static_cast<unsigned char>(bytes_[pos_]); }

  void advance() {
    if (bytes_[pos_] == '\n') {
      ++line_;
      col_ = 1;
    } else {
      ++col_;
    }
    ++pos_;
  }

  static bool is_space(unsigned char b) {
    return b == ' ' || b == '\t' || b == '\n' || b == '\r' || b == '\v' || b == '\f';
  }

  // Whitespace and `#` comments (to the end of the line).
  void skip_blanks() {
    while (!at_end()) {
      if (is_space(peek())) {
        advance();
      } else if (peek() == '#') {
        while (!at_end() && peek() != '\n' && peek() != '\r') advance();
      } else {
        break;
      }
    }
  }

  // `file:line:column: ` at the cursor.
  std::string where() const {
    return std::string(file_) + ":" + std::to_string(line_) + ":" + std::to_string(col_) + ": ";
  }

  [[noreturn]] void fail(const std::string& message) const { throw ImageError(where() + message); }

  // A decimal integer after blanks; `what` names it in messages.
  std::int64_t number(const char* what) {
    skip_blanks();
    if (at_end()) fail(std::string("unexpected end of file, expected ") + what);
    if (peek() < '0' || peek() > '9') fail(std::string("expected ") + what + ", found " + describe(bytes_, pos_));
    const Cursor start = *this;
    std::int64_t v = 0;
    while (!at_end() && peek() >= '0' && peek() <= '9') {
      if (v > 1'000'000'000'000) start.fail(std::string(what) + " is absurdly large");
      v = v * 10 + (peek() - '0');
      advance();
    }
    if (!at_end() && !is_space(peek()) && peek() != '#')
      fail(std::string("expected whitespace after ") + what + ", found " + describe(bytes_, pos_));
    return v;
  }

 private:
  std::string_view bytes_;
  std::string_view file_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int col_ = 1;
};

#if BCCMIS_APPS_HAVE_STB
// The PNG's samples decoded by `load` (stb's 8- or 16-bit loader, one
// channel) into f.values as sample / maxval; its size must be f's.
template <class Sample, class Load>
void decode_png(Load load, const stbi_uc* data, int len, double maxval, const std::string& name, HeightField& f) {
  int w = 0, h = 0, channels = 0;
  std::unique_ptr<Sample, void (*)(void*)> px(load(data, len, &w, &h, &channels, 1), stbi_image_free);
  if (!px || w != f.width || h != f.height)
    throw ImageError(name +
                     ": cannot decode the PNG: " + (stbi_failure_reason() ? stbi_failure_reason() : "unknown error"));
  for (std::size_t i = 0; i < f.values.size(); ++i) f.values[i] = static_cast<double>(px.get()[i]) / maxval;
}
#endif

}  // namespace

HeightField parse_pgm(std::string_view bytes, std::string_view file, const ImageLimits& limits) {
  Cursor cur(bytes, file);
  if (bytes.size() < 2 || bytes[0] != 'P') {
    if (bytes.empty()) cur.fail("empty file, expected a PGM image (magic P2 or P5)");
    cur.fail("wrong magic: expected P2 or P5 (a PGM image), found " + describe(bytes, 0));
  }
  const char kind = bytes[1];
  if (kind != '2' && kind != '5') {
    std::string magic(1, 'P');
    if (kind >= 0x21 && kind < 0x7f)
      magic += kind;
    else
      magic += hex_byte(static_cast<unsigned char>(kind));
    std::string hint;
    if (kind == '3' || kind == '6') hint = " (a colour PPM; convert it with ppmtopgm)";
    if (kind == '1' || kind == '4') hint = " (a bitmap PBM; convert it with pbmtopgm or pamdepth)";
    if (kind == '7') hint = " (a PAM; convert it with pamtopnm)";
    cur.fail("wrong magic '" + magic + "'" + hint + ": expected P2 or P5 (a PGM image)");
  }
  cur.advance();
  cur.advance();
  if (!cur.at_end() && !Cursor::is_space(cur.peek()) && cur.peek() != '#')
    cur.fail("expected whitespace after the magic, found " + describe(bytes, cur.pos()));

  HeightField f;
  f.format = kind == '2' ? "P2" : "P5";
  const Cursor width_at = [&] {
    Cursor c = cur;
    c.skip_blanks();
    return c;
  }();
  const std::int64_t w = cur.number("the width");
  const std::int64_t h = cur.number("the height");
  check_size(w, h, limits, width_at.where());
  const Cursor maxval_at = [&] {
    Cursor c = cur;
    c.skip_blanks();
    return c;
  }();
  const std::int64_t maxval = cur.number("the maxval");
  if (maxval < 1 || maxval > 65535) maxval_at.fail("maxval " + std::to_string(maxval) + " is out of range 1..65535");
  f.width = w;
  f.height = h;
  f.maxval = static_cast<int>(maxval);
  const std::size_t count = static_cast<std::size_t>(w * h);
  const double scale = 1.0 / static_cast<double>(maxval);

  if (kind == '5') {
    // Exactly one whitespace byte separates maxval from the raster.
    if (cur.at_end()) cur.fail("unexpected end of file after the maxval, expected the raster");
    if (!Cursor::is_space(cur.peek()))
      cur.fail("expected one whitespace byte after the maxval, found " + describe(bytes, cur.pos()));
    cur.advance();
    const std::size_t start = cur.pos();
    const std::size_t bps = maxval > 255 ? 2 : 1;
    const std::size_t need = count * bps;
    const std::size_t have = bytes.size() - start;
    if (have < need)
      throw ImageError(std::string(file) + ": byte " + std::to_string(bytes.size()) +
                       ": truncated raster: " + std::to_string(w) + "x" + std::to_string(h) + " samples of " +
                       std::to_string(bps) + (bps == 1 ? " byte" : " bytes") + " need " + std::to_string(need) +
                       " bytes from byte " + std::to_string(start) + ", the file has " + std::to_string(have));
    f.values.resize(count);
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data() + start);
    for (std::size_t i = 0; i < count; ++i) {
      const unsigned v = bps == 2 ? (unsigned{p[2 * i]} << 8) | p[2 * i + 1] : p[i];
      if (v > static_cast<unsigned>(maxval))
        throw ImageError(std::string(file) + ": byte " + std::to_string(start + i * bps) + ": sample " +
                         std::to_string(v) + " exceeds maxval " + std::to_string(maxval) + " (row " +
                         std::to_string(static_cast<std::int64_t>(i) / w) + ", column " +
                         std::to_string(static_cast<std::int64_t>(i) % w) + ")");
      f.values[i] = static_cast<double>(v) * scale;
    }
    return f;
  }

  // P2: whitespace-separated decimal samples.
  f.values.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    cur.skip_blanks();
    if (cur.at_end())
      cur.fail("unexpected end of file: the raster has " + std::to_string(i) + " of " + std::to_string(count) +
               " samples (" + std::to_string(w) + "x" + std::to_string(h) + ")");
    const Cursor at = cur;
    const std::int64_t v = cur.number("a sample");
    if (v > maxval)
      at.fail("sample " + std::to_string(v) + " exceeds maxval " + std::to_string(maxval) + " (row " +
              std::to_string(static_cast<std::int64_t>(i) / w) + ", column " +
              std::to_string(static_cast<std::int64_t>(i) % w) + ")");
    f.values[i] = static_cast<double>(v) * scale;
  }
  cur.skip_blanks();
  if (!cur.at_end())
    cur.fail("unexpected " + describe(bytes, cur.pos()) + " after the " + std::to_string(count) + " samples");
  return f;
}

bool png_supported() { return BCCMIS_APPS_HAVE_STB != 0; }

HeightField parse_png(std::string_view bytes, std::string_view file, const ImageLimits& limits) {
  const std::string name(file);
#if BCCMIS_APPS_HAVE_STB
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw ImageError(name + ": file too large for the PNG decoder");
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int len = static_cast<int>(bytes.size());
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(data, len, &w, &h, &channels))
    throw ImageError(name +
                     ": not a readable PNG: " + (stbi_failure_reason() ? stbi_failure_reason() : "unknown error"));
  check_size(w, h, limits, name + ": ");
  const bool sixteen = stbi_is_16_bit_from_memory(data, len) != 0;
  HeightField f;
  f.width = w;
  f.height = h;
  f.format = "PNG";
  f.maxval = sixteen ? 65535 : 255;
  const std::size_t count = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  f.values.resize(count);
  if (sixteen)
    decode_png<stbi_us>(stbi_load_16_from_memory, data, len, 65535.0, name, f);
  else
    decode_png<stbi_uc>(stbi_load_from_memory, data, len, 255.0, name, f);
  return f;
#else
  (void)bytes;
  (void)limits;
  throw ImageError(name +
                   ": PNG input is not available in this build (stb_image was not found; install libstb-dev "
                   "and reconfigure, or convert the image with `pngtopam x.png > x.pgm`)");
#endif
}

HeightField parse_height_field(std::string_view bytes, std::string_view file, const ImageLimits& limits) {
  static constexpr std::string_view png_magic = "\x89PNG\r\n\x1a\n";
  if (bytes.substr(0, png_magic.size()) == png_magic) return parse_png(bytes, file, limits);
  if (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7') return parse_pgm(bytes, file, limits);
  const std::string name(file);
  if (bytes.empty()) throw ImageError(name + ": empty file, expected a PGM or PNG image");
  throw ImageError(name + ": not a PGM (P2/P5) or PNG image: it starts with " + describe(bytes, 0) +
                   (bytes.size() > 1 ? " " + describe(bytes, 1) : std::string()));
}

HeightField read_height_field(const std::string& path, const ImageLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ImageError(path + ": cannot open for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw ImageError(path + ": read error");
  return parse_height_field(ss.str(), path, limits);
}

std::string format_pgm(const HeightField& f, int maxval, bool plain) {
  maxval = std::clamp(maxval, 1, 65535);
  std::string out = std::string(plain ? "P2" : "P5") + "\n" + std::to_string(f.width) + " " + std::to_string(f.height) +
                    "\n" + std::to_string(maxval) + "\n";
  std::int64_t col = 0;
  for (const double v : f.values) {
    const auto q = static_cast<unsigned>(std::lround(std::clamp(v, 0.0, 1.0) * maxval));
    if (plain) {
      out += std::to_string(q);
      out += ++col == f.width ? '\n' : ' ';
      if (col == f.width) col = 0;
    } else if (maxval > 255) {
      out += static_cast<char>(q >> 8);
      out += static_cast<char>(q & 0xff);
    } else {
      out += static_cast<char>(q);
    }
  }
  return out;
}

}  // namespace bccmis
