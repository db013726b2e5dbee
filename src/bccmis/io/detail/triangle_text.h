// bccmis::io::detail: a triangle mesh's numbers as text, shared by the
// .obj, .ply and .vtu writers of the height-field mesh. They write through
// TextWriter (bccmis/text_writer.h) into its buffer.
#pragma once

#include <array>
#include <bit>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "bccmis/text_writer.h"

namespace bccmis::io::detail {

// The most bytes of the shortest round-trip text of a double (std::to_chars).
inline constexpr std::size_t kDoubleBytes = 32;

// Shortest text that reads back as the same double; returns its end.
inline char* write_double(char* p, double v) { return std::to_chars(p, p + kDoubleBytes, v).ptr; }

// write_double for values that recur: a mesh's x and y take few distinct
// values (multiples of the finest cell side), so the texts of recent values
// are kept in a small direct-mapped table and copied.
class RecurringDoubles {
 public:
  char* write(char* p, double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    Entry& e = entries_[(bits * 0x9E3779B97F4A7C15ull) >> (64 - kBits)];
    if (!e.used || e.bits != bits) {
      e.bits = bits;
      e.used = true;
      e.size = static_cast<std::size_t>(write_double(e.text, v) - e.text);
    }
    std::memcpy(p, e.text, kDoubleBytes);
    return p + e.size;
  }

 private:
  static constexpr int kBits = 12;
  struct Entry {
    std::uint64_t bits = 0;
    bool used = false;
    std::size_t size = 0;
    char text[kDoubleBytes] = {};
  };
  std::vector<Entry> entries_ = std::vector<Entry>(std::size_t{1} << kBits);
};

// Comment text on one line.
inline std::string one_line(std::string_view s) {
  std::string r(s);
  for (char& ch : r)
    if (ch == '\n' || ch == '\r') ch = ' ';
  return r;
}

// Room for a line of three doubles and a few more bytes.
inline constexpr std::size_t kLine = 3 * kDoubleBytes + 4 * TextWriter::kIntBytes + 32;

// "x y z" of a vertex (no newline).
inline char* write_xyz(char* p, RecurringDoubles& xy, const std::array<double, 3>& v) {
  p = xy.write(p, v[0]);
  *p++ = ' ';
  p = xy.write(p, v[1]);
  *p++ = ' ';
  return write_double(p, v[2]);
}

// A line `prefix` "x y z" for each vertex (prefix: at most 32 bytes).
inline void write_vertex_lines(TextWriter& w, const std::vector<std::array<double, 3>>& vertices,
                               std::string_view prefix) {
  RecurringDoubles xy;
  for (const auto& v : vertices) {
    char* p = w.room(kLine);
    std::memcpy(p, prefix.data(), prefix.size());
    p = write_xyz(p + prefix.size(), xy, v);
    *p++ = '\n';
    w.commit(p);
  }
}

// "a b c" of a triangle, each index plus `base` (no newline).
inline char* write_triangle(char* p, const std::array<std::size_t, 3>& t, std::size_t base) {
  p = TextWriter::write_uint(p, t[0] + base);
  *p++ = ' ';
  p = TextWriter::write_uint(p, t[1] + base);
  *p++ = ' ';
  return TextWriter::write_uint(p, t[2] + base);
}

// The text `write` writes to a stream.
template <class Write>
std::string text_of(const Write& write) {
  std::ostringstream out;
  write(out);
  return std::move(out).str();
}

}  // namespace bccmis::io::detail
