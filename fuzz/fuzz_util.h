// Helpers shared by the fuzz targets: failing loudly with a replayable trace,
// the shape every ParseError must have, and the byte decoder of the
// operation-sequence targets (fuzz_refine_coarsen, fuzz_differential).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "bccmis/format.h"
#include "bccmis/geometry.h"
#include "bccmis/graph.h"
#include "bccmis/ops.h"

namespace bccmis::fuzz {

/// Prints `what` and, if given, the equivalent text trace (readable by
/// `bccmis replay`) to stderr, then aborts so that the fuzzing engine records
/// a crash. With BCCMIS_FUZZ_TRACE=path in the environment the trace is also
/// written to that file.
[[noreturn]] inline void fail(std::string_view target, const std::string& what, const Trace* trace = nullptr) {
  std::string text = "# " + std::string(target) + ": " + what + "\n";
  if (trace) text += format_trace(*trace);
  std::fprintf(stderr, "\n==== %.*s failure: %s\n", static_cast<int>(target.size()), target.data(), what.c_str());
  if (trace) {
    std::fprintf(stderr, "==== equivalent trace (bccmis replay FILE):\n%s==== end of trace\n", text.c_str());
    if (const char* path = std::getenv("BCCMIS_FUZZ_TRACE")) {
      std::ofstream out(path, std::ios::binary);
      out << text;
    }
  }
  std::fflush(stderr);
  std::abort();
}

/// A parse error must be one printable line `file:line:column: message` that
/// points into the text: 1 <= line <= number of lines, 1 <= column <= length
/// of that line + 1.
inline void check_parse_error(std::string_view target, const ParseError& e, std::string_view file,
                              std::string_view text) {
  auto bad = [&](const std::string& why) { fail(target, "malformed ParseError (" + why + "): " + e.what()); };
  const std::string what = e.what();
  if (e.file != file) bad("wrong file name");
  const std::string prefix =
      std::string(file) + ":" + std::to_string(e.line) + ":" + std::to_string(e.column) + ": ";
  if (what.compare(0, prefix.size(), prefix) != 0 || what.size() == prefix.size()) bad("not file:line:column: message");
  if (what.substr(prefix.size()) != e.message) bad("what() does not end with message");
  for (char ch : what) {
    const auto u = static_cast<unsigned char>(ch);
    if (u < 0x20 || u >= 0x7f) bad("unprintable byte in the message");
  }
  if (what.size() > 1000) bad("message longer than 1000 bytes");
  // Locate line e.line in text.
  std::size_t start = 0;
  int line = 1;
  while (line < e.line) {
    const std::size_t nl = text.find('\n', start);
    if (nl == std::string_view::npos) bad("line number past the end of the text");
    start = nl + 1;
    ++line;
  }
  if (e.line < 1) bad("line number < 1");
  const std::size_t end = text.find('\n', start);
  const std::size_t length = (end == std::string_view::npos ? text.size() : end) - start;
  if (e.column < 1 || static_cast<std::size_t>(e.column) > length + 1) bad("column outside the line");
}

/// The fuzzer's bytes, read front to back; past the end every byte is 0.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const { return pos_ >= size_; }
  std::uint8_t next() { return pos_ < size_ ? data_[pos_++] : 0; }
  /// An index below `n` (n > 0): one byte, or two when n > 256.
  std::size_t index(std::size_t n) {
    std::size_t k = next();
    if (n > 256) k |= std::size_t{next()} << 8;
    return k % n;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

/// A lattice from three bytes: W = 1 + b0 % max_side, H = 1 + b1 % max_side,
/// L = b2 % levels.
inline LatticeSize decode_lattice(Bytes& in, int max_side, int levels) {
  LatticeSize size;
  size.W = 1 + in.next() % max_side;
  size.H = 1 + in.next() % max_side;
  size.L = in.next() % levels;
  return size;
}

/// The k-th element of a sorted set.
template <class Set>
typename Set::value_type nth(const Set& s, std::size_t k) {
  return *std::next(s.begin(), static_cast<std::ptrdiff_t>(k));
}

/// Decodes the operands of one operation with selector byte `s` (its low
/// three bits) against the reference state g and calls refine(p) or
/// coarsen(p):
///   0, 1, 2  refine the k-th live center             (k: 1 byte, 2 if |C| > 256)
///   3, 4     coarsen the k-th node at a refined cell's center (mostly legal;
///            nothing when there is none)
///   5        coarsen the k-th node of N (mostly refused)
///   6        refine at a raw position (x, y)          (2 bytes; mostly refused)
///   7        coarsen at a raw position (x, y)         (2 bytes; mostly refused)
/// A raw coordinate byte b is b % (extent + 3) - 1 (a little beyond the domain
/// on every side), except 0xff = INT64_MAX and 0xfe = INT64_MIN.
template <class Refine, class Coarsen>
void decode_operation(Bytes& in, std::uint8_t s, const Graph& g, const Refine& refine, const Coarsen& coarsen) {
  switch (s & 7) {
    case 0:
    case 1:
    case 2:
      refine(nth(g.C, in.index(g.C.size())));
      break;
    case 3:
    case 4: {
      std::vector<Point> refined;
      for (const Point& n : g.N)
        if (refined_center_level(g.size, n)) refined.push_back(n);
      if (refined.empty()) break;
      coarsen(refined[in.index(refined.size())]);
      break;
    }
    case 5:
      coarsen(nth(g.N, in.index(g.N.size())));
      break;
    default: {
      const std::int64_t S = level0_side(g.size);
      auto coordinate = [&](std::int64_t extent) -> std::int64_t {
        const std::uint8_t b = in.next();
        if (b == 0xff) return INT64_MAX;
        if (b == 0xfe) return INT64_MIN;
        return static_cast<std::int64_t>(b) % (extent + 3) - 1;
      };
      // Sequenced: x is read before y.
      const std::int64_t x = coordinate(g.size.W * S);
      const std::int64_t y = coordinate(g.size.H * S);
      if ((s & 7) == 6)
        refine(Point{x, y});
      else
        coarsen(Point{x, y});
      break;
    }
  }
}

}  // namespace bccmis::fuzz
