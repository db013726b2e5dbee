// The byte programs of the operation-sequence fuzz targets (fuzz_refine_coarsen,
// fuzz_differential): every byte string is a valid program, GEOS/fmt style.
// Three bytes give the lattice; then each operation is a selector byte and
// its operands, decoded against the current reference state, so that most
// operations name live vertices and deep states are reached fast.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

#include "bccmis/geometry.h"
#include "bccmis/graph.h"

namespace bccmis::testing {

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
    case 2: refine(nth(g.C, in.index(g.C.size()))); break;
    case 3:
    case 4: {
      std::vector<Point> refined;
      for (const Point& n : g.N)
        if (refined_center_level(g.size, n)) refined.push_back(n);
      if (refined.empty()) break;
      coarsen(refined[in.index(refined.size())]);
      break;
    }
    case 5: coarsen(nth(g.N, in.index(g.N.size()))); break;
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

/// The driver loop: up to `max_ops` operations while bytes are left. Each
/// reads a selector byte s, decodes its operands against g (which the
/// callbacks keep current) and calls refine(p, s) or coarsen(p, s), then
/// after(s); the high bits of s are the target's own flags.
template <class Refine, class Coarsen, class After>
void run_program(Bytes& in, std::size_t max_ops, const Graph& g, const Refine& refine, const Coarsen& coarsen,
                 const After& after) {
  for (std::size_t op = 0; op < max_ops && !in.empty(); ++op) {
    const std::uint8_t s = in.next();
    decode_operation(
        in, s, g, [&](const Point& p) { refine(p, s); }, [&](const Point& p) { coarsen(p, s); });
    after(s);
  }
}

}  // namespace bccmis::testing
