// The byte programs of the operation-sequence fuzz targets (fuzz_refine_coarsen,
// fuzz_refine_coarsen_3d, fuzz_differential): every byte string is a valid
// program, GEOS/fmt style. Three bytes (four in 3D) give the lattice; then
// each operation is a selector byte and its operands, decoded against the
// current reference state, so that most operations name live vertices and
// deep states are reached fast. Written once for every lattice
// (bccmis/lattice.h): the 2D Graph and the 3D d3::Graph decode alike, a raw
// position reading one byte per coordinate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

#include "bccmis/geometry.h"
#include "bccmis/graph.h"
#include "bccmis/lattice.h"

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
/// L = b2 % levels; a size with a depth (d3::LatticeSize) reads four:
/// W, H, D = 1 + b2 % max_side, then L = b3 % levels.
template <class Size = LatticeSize>
Size decode_lattice(Bytes& in, int max_side, int levels) {
  Size size;
  size.W = 1 + in.next() % max_side;
  size.H = 1 + in.next() % max_side;
  if constexpr (requires { size.D; }) size.D = 1 + in.next() % max_side;
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
///   6        refine at a raw position (x, y[, z])    (one byte per coordinate; mostly refused)
///   7        coarsen at a raw position (x, y[, z])   (one byte per coordinate; mostly refused)
/// A raw coordinate byte b is b % (extent + 3) - 1 (a little beyond the domain
/// on every side), except 0xff = INT64_MAX and 0xfe = INT64_MIN.
template <AdaptiveLattice L, class Refine, class Coarsen>
void decode_operation(Bytes& in, std::uint8_t s, const L& g, const Refine& refine, const Coarsen& coarsen) {
  const auto& size = size_of(g);
  switch (s & 7) {
    case 0:
    case 1:
    case 2: refine(nth(cells(g), in.index(cell_count(g)))); break;
    case 3:
    case 4: {
      std::vector<point_type_t<L>> refined;
      for (const auto& n : nodes(g))
        if (refined_center_level(size, n)) refined.push_back(n);
      if (refined.empty()) break;
      coarsen(refined[in.index(refined.size())]);
      break;
    }
    case 5: coarsen(nth(nodes(g), in.index(node_count(g)))); break;
    default: {
      const std::int64_t S = level0_side(size);
      auto coordinate = [&](std::int64_t extent) -> std::int64_t {
        const std::uint8_t b = in.next();
        if (b == 0xff) return INT64_MAX;
        if (b == 0xfe) return INT64_MIN;
        return static_cast<std::int64_t>(b) % (extent + 3) - 1;
      };
      // Sequenced: x is read before y, y before z.
      point_type_t<L> p;
      p.x = coordinate(size.W * S);
      p.y = coordinate(size.H * S);
      if constexpr (L::dimension == 3) p.z = coordinate(size.D * S);
      if ((s & 7) == 6)
        refine(p);
      else
        coarsen(p);
      break;
    }
  }
}

/// The driver loop: up to `max_ops` operations while bytes are left. Each
/// reads a selector byte s, decodes its operands against g (which the
/// callbacks keep current) and calls refine(p, s) or coarsen(p, s), then
/// after(s); the high bits of s are the target's own flags.
template <AdaptiveLattice L, class Refine, class Coarsen, class After>
void run_program(Bytes& in, std::size_t max_ops, const L& g, const Refine& refine, const Coarsen& coarsen,
                 const After& after) {
  using P = point_type_t<L>;
  for (std::size_t op = 0; op < max_ops && !in.empty(); ++op) {
    const std::uint8_t s = in.next();
    decode_operation(
        in, s, g, [&](const P& p) { refine(p, s); }, [&](const P& p) { coarsen(p, s); });
    after(s);
  }
}

}  // namespace bccmis::testing
