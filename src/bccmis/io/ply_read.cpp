// The PLY reader (ply.h; spec/formats.md, "PLY input"): the text header, then
// the elements in the order the header declares them, read by one loop over
// either of two value sources, ASCII tokens or binary bytes.
#include "bccmis/io/ply.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bccmis/io/detail/line_scanner.h"

namespace bccmis::io {

namespace {

enum class Scalar { i8, u8, i16, u16, i32, u32, f32, f64 };

std::optional<Scalar> scalar_named(std::string_view name) {
  if (name == "char" || name == "int8") return Scalar::i8;
  if (name == "uchar" || name == "uint8") return Scalar::u8;
  if (name == "short" || name == "int16") return Scalar::i16;
  if (name == "ushort" || name == "uint16") return Scalar::u16;
  if (name == "int" || name == "int32") return Scalar::i32;
  if (name == "uint" || name == "uint32") return Scalar::u32;
  if (name == "float" || name == "float32") return Scalar::f32;
  if (name == "double" || name == "float64") return Scalar::f64;
  return std::nullopt;
}

std::size_t size_of(Scalar s) {
  switch (s) {
    case Scalar::i8:
    case Scalar::u8: return 1;
    case Scalar::i16:
    case Scalar::u16: return 2;
    case Scalar::i32:
    case Scalar::u32:
    case Scalar::f32: return 4;
    case Scalar::f64: return 8;
  }
  return 0;
}

bool is_integer(Scalar s) { return s != Scalar::f32 && s != Scalar::f64; }

struct Property {
  std::string name;
  Scalar type = Scalar::f64;    // of a list: of its items
  std::optional<Scalar> count;  // a list: the type of its count
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

enum class Encoding { ascii, little_endian, big_endian };

struct Header {
  Encoding encoding = Encoding::ascii;
  std::vector<Element> elements;
};

/// What the body's loop is reading, for messages: "vertex 3, property 'z'".
struct Place {
  const Element* element = nullptr;
  std::uint64_t index = 0;
  const Property* property = nullptr;
  std::string text() const {
    return element->name + " " + std::to_string(index) + ", property '" + property->name + "'";
  }
};

/// The header, up to and including `end_header`; the scanner is left on that
/// line. Refuses what the body's loop could not read: no format line, an
/// unknown type, a list coordinate, no x, y or z, a face without its list.
Header read_header(detail::LineScanner& t) {
  Header h;
  bool format = false;
  if (!t.next_line() || t.token(false) != "ply") t.fail("expected 'ply' on the first line");
  if (!t.token(false).empty()) t.fail("expected nothing after 'ply' on the first line");
  auto scalar = [&](std::string_view what) {
    const std::string_view w = t.token(false);
    const auto s = scalar_named(w);
    if (!s)
      t.fail("unknown " + std::string(what) + " '" + std::string(w) +
             "' (expected char, uchar, short, ushort, int, uint, float, double, or int8 ... float64)");
    return *s;
  };
  for (;;) {
    if (!t.next_line()) t.fail("unexpected end of file in the header (expected 'end_header')");
    const std::string_view key = t.token(false);
    if (key.empty() || key == "comment" || key == "obj_info") continue;
    if (key == "end_header") break;
    if (key == "format") {
      const std::string_view enc = t.token(false);
      if (enc == "ascii") {
        h.encoding = Encoding::ascii;
      } else if (enc == "binary_little_endian") {
        h.encoding = Encoding::little_endian;
      } else if (enc == "binary_big_endian") {
        h.encoding = Encoding::big_endian;
      } else {
        t.fail("unsupported format '" + std::string(enc) +
               "' (expected ascii, binary_little_endian or binary_big_endian)");
      }
      const std::string_view version = t.token(false);
      if (version != "1.0") t.fail("unsupported PLY version '" + std::string(version) + "' (expected 1.0)");
      format = true;
    } else if (key == "element") {
      Element e;
      e.name = std::string(t.token(false));
      if (e.name.empty()) t.fail("expected the element's name");
      const long long n = t.integer(t.token(false), "the element's count");
      if (n < 0) t.fail("negative count of element '" + e.name + "'");
      e.count = static_cast<std::uint64_t>(n);
      for (const Element& old : h.elements)
        if (old.name == e.name && (e.name == "vertex" || e.name == "face")) t.fail("a second element '" + e.name + "'");
      if (e.name == "vertex" && e.count > 0xffffffffULL) t.fail("too many vertices");
      h.elements.push_back(std::move(e));
    } else if (key == "property") {
      if (h.elements.empty()) t.fail("a property before any element");
      Element& e = h.elements.back();
      Property p;
      if (t.line_blank()) t.fail("expected the property's type");
      const std::string_view first = t.token(false);
      if (first == "list") {
        p.count = scalar("list count type");
        if (!is_integer(*p.count)) t.fail("a list's count type must be an integer type");
        p.type = scalar("list item type");
      } else {
        const auto s = scalar_named(first);
        if (!s)
          t.fail("unknown property type '" + std::string(first) +
                 "' (expected char, uchar, short, ushort, int, uint, float, double, or int8 ... float64)");
        p.type = *s;
      }
      p.name = std::string(t.token(false));
      if (p.name.empty()) t.fail("expected the property's name");
      const bool coordinate = p.name == "x" || p.name == "y" || p.name == "z";
      if (e.name == "vertex" && coordinate && p.count) t.fail("vertex coordinate '" + p.name + "' is a list");
      if (e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index")) {
        if (!p.count) t.fail("face property '" + p.name + "' is not a list");
        if (!is_integer(p.type)) t.fail("face property '" + p.name + "' has items of a floating-point type");
      }
      e.properties.push_back(std::move(p));
    } else {
      t.fail("unknown header line '" + std::string(key) +
             "' (expected format, element, property, comment, obj_info or end_header)");
    }
  }
  if (!format) t.fail("no 'format' line before 'end_header'");
  bool vertex = false, face = false;
  for (const Element& e : h.elements) {
    auto has = [&](std::string_view name) {
      for (const Property& p : e.properties)
        if (p.name == name) return true;
      return false;
    };
    if (e.name == "vertex") {
      vertex = true;
      for (const char* c : {"x", "y", "z"})
        if (!has(c)) t.fail(std::string("element 'vertex' has no property '") + c + "'");
    }
    if (e.name == "face") {
      face = true;
      if (!has("vertex_indices") && !has("vertex_index"))
        t.fail("element 'face' has no list property 'vertex_indices' (or 'vertex_index')");
    }
  }
  if (!vertex) t.fail("no element 'vertex' in the header");
  if (!face) t.fail("no element 'face' in the header (a point cloud is no surface)");
  return h;
}

/// The values of an ASCII body: whitespace-separated tokens, across lines.
class AsciiValues {
 public:
  explicit AsciiValues(detail::LineScanner& t) : t_(t) {}
  double number(const Place& at) { return t_.number(token(at), at.text()); }
  long long integer(Scalar, const Place& at) { return t_.integer(token(at), at.text()); }
  void skip(Scalar, const Place& at) { token(at); }
  std::size_t line() const { return t_.line(); }
  [[noreturn]] void fail(const std::string& what) const { t_.fail(what); }
  void finish() {
    for (;;) {
      if (!t_.token(false).empty()) t_.fail("unexpected text after the last element");
      if (!t_.next_line()) return;
    }
  }

 private:
  std::string_view token(const Place& at) {
    for (;;) {
      const std::string_view w = t_.token(false);
      if (!w.empty()) return w;
      if (!t_.next_line()) t_.fail("unexpected end of file in " + at.text());
    }
  }
  detail::LineScanner& t_;
};

/// The values of a binary body from byte `start`, little- or big-endian.
class BinaryValues {
 public:
  BinaryValues(const std::string& file, const std::string& data, std::size_t start, bool little)
      : file_(file), data_(data), pos_(start), little_(little) {}
  double number(const Place& at) {
    const Scalar s = at.property->type;
    const std::uint64_t b = bytes(s, at);
    double x = 0;
    switch (s) {
      case Scalar::f32: x = std::bit_cast<float>(static_cast<std::uint32_t>(b)); break;
      case Scalar::f64: x = std::bit_cast<double>(b); break;
      default: x = static_cast<double>(as_integer(s, b)); break;
    }
    if (!std::isfinite(x)) fail(at.text() + " is not a finite number");
    return x;
  }
  long long integer(Scalar s, const Place& at) { return as_integer(s, bytes(s, at)); }
  void skip(Scalar s, const Place& at) { bytes(s, at); }
  std::size_t line() const { return 0; }
  [[noreturn]] void fail(const std::string& what) const {
    throw ReadError(file_ + ": byte " + std::to_string(value_) + ": " + what);
  }
  void finish() {
    value_ = pos_;
    if (pos_ != data_.size())
      fail(std::to_string(data_.size() - pos_) + " bytes after the last element (" + std::to_string(pos_) +
           " bytes expected)");
  }

 private:
  /// The `size_of(s)` bytes at the position as an unsigned number.
  std::uint64_t bytes(Scalar s, const Place& at) {
    const std::size_t n = size_of(s);
    value_ = pos_;
    if (data_.size() - pos_ < n) fail("binary PLY truncated in " + at.text());
    std::uint64_t b = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto byte = static_cast<std::uint64_t>(static_cast<unsigned char>(data_[pos_ + (little_ ? i : n - 1 - i)]));
      b |= byte << (8 * i);
    }
    pos_ += n;
    return b;
  }
  static long long as_integer(Scalar s, std::uint64_t b) {
    switch (s) {
      case Scalar::i8: return static_cast<std::int8_t>(b);
      case Scalar::u8: return static_cast<std::uint8_t>(b);
      case Scalar::i16: return static_cast<std::int16_t>(b);
      case Scalar::u16: return static_cast<std::uint16_t>(b);
      case Scalar::i32: return static_cast<std::int32_t>(b);
      case Scalar::u32: return static_cast<std::uint32_t>(b);
      default: return 0;  // floating-point types are refused in the header where an integer is needed
    }
  }
  const std::string& file_;
  const std::string& data_;
  std::size_t pos_;
  std::size_t value_ = 0;
  bool little_;
};

/// The elements of the body in the header's order: coordinates from `vertex`,
/// fanned polygons from `face`, everything else read past.
template <class Values>
void read_body(Values& in, const Header& h, TriangleSoup& s) {
  std::uint64_t vertex_count = 0;
  for (const Element& e : h.elements)
    if (e.name == "vertex") vertex_count = e.count;
  std::vector<std::uint32_t> poly;
  for (const Element& e : h.elements) {
    if (e.properties.empty()) continue;  // its instances take no room: nothing to read, however many
    const bool vertex = e.name == "vertex", face = e.name == "face";
    Place at{&e, 0, nullptr};
    for (at.index = 0; at.index < e.count; ++at.index) {
      d3::Vec3 p{0, 0, 0};
      bool polygon_read = false;
      for (const Property& prop : e.properties) {
        at.property = &prop;
        if (prop.count) {
          const long long n = in.integer(*prop.count, at);
          if (n < 0) in.fail(at.text() + ": negative list count " + std::to_string(n));
          const bool indices = face && !polygon_read && (prop.name == "vertex_indices" || prop.name == "vertex_index");
          if (!indices) {
            for (long long i = 0; i < n; ++i) in.skip(prop.type, at);
            continue;
          }
          polygon_read = true;
          if (n < 3)
            in.fail("face " + std::to_string(at.index) + " has " + std::to_string(n) + " vertices (at least 3 needed)");
          poly.clear();
          for (long long i = 0; i < n; ++i) {
            const long long v = in.integer(prop.type, at);
            if (v < 0 || static_cast<std::uint64_t>(v) >= vertex_count)
              in.fail("face " + std::to_string(at.index) + ": vertex index " + std::to_string(v) + " out of range (" +
                      std::to_string(vertex_count) + " vertices)");
            poly.push_back(static_cast<std::uint32_t>(v));
          }
          detail::add_polygon(s, poly, static_cast<std::size_t>(at.index), in.line());
        } else if (vertex && (prop.name == "x" || prop.name == "y" || prop.name == "z")) {
          p[static_cast<std::size_t>(prop.name[0] - 'x')] = in.number(at);
        } else {
          in.skip(prop.type, at);
        }
      }
      if (vertex) s.vertices.push_back(p);
    }
  }
  in.finish();
}

}  // namespace

TriangleSoup read_ply(const std::string& file, const std::string& data) {
  detail::LineScanner t(file, data);
  const Header h = read_header(t);
  TriangleSoup s;
  if (h.encoding == Encoding::ascii) {
    AsciiValues in(t);
    read_body(in, h, s);
  } else {
    BinaryValues in(file, data, t.offset(), h.encoding == Encoding::little_endian);
    read_body(in, h, s);
  }
  return s;
}

}  // namespace bccmis::io
