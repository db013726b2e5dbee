// bccmis::d3::detail: the order of distinct lattice points by position
// (spec/stuffing.md S8a): the numbering of the flat stuffer and the fast 3D
// lattice's cells in order (spec/lattice3d.md §9.7).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "bccmis/d3/point.h"

namespace bccmis::d3::detail {

/// The indices 0 .. n - 1 of `points` (distinct, n < 2^32) in increasing
/// d3::Point order. S8a: when the points' packed offsets and the index fit
/// in 64 bits, an LSD radix sort of the packed keys (digits above the
/// index's bits only: the keys are distinct); otherwise std::sort. Both give
/// the one sorted order of distinct points.
inline std::vector<std::uint32_t> position_order(std::span<const d3::Point> points) {
  const std::size_t n = points.size();
  std::vector<std::uint32_t> order(n);
  if (n == 0) return order;
  std::array<std::int64_t, 3> low = points[0].axes(), high = low;
  for (const d3::Point& p : points) {
    const auto a = p.axes();
    for (std::size_t d = 0; d < 3; ++d) low[d] = std::min(low[d], a[d]), high[d] = std::max(high[d], a[d]);
  }
  // S8a: offset o_d = p_d - low_d, b_d bits each, the key
  // o_x << (b_y + b_z) | o_y << b_z | o_z, then the index below it.
  std::array<int, 3> bits{};
  for (std::size_t d = 0; d < 3; ++d)
    bits[d] =
        static_cast<int>(std::bit_width(static_cast<std::uint64_t>(high[d]) - static_cast<std::uint64_t>(low[d])));
  const int index_bits = static_cast<int>(std::bit_width(n - 1));
  const int key_bits = bits[0] + bits[1] + bits[2];
  if (key_bits + index_bits > 64) {
    for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return points[a] < points[b]; });
    return order;
  }
  std::vector<std::uint64_t> keys(n), buffer(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto a = points[i].axes();
    std::uint64_t k = 0;
    for (std::size_t d = 0; d < 3; ++d)
      k = (k << bits[d]) | (static_cast<std::uint64_t>(a[d]) - static_cast<std::uint64_t>(low[d]));
    keys[i] = (k << index_bits) | i;
  }
  constexpr int kDigit = 11;
  std::vector<std::uint32_t> count(std::size_t{1} << kDigit);
  for (int shift = index_bits; shift < index_bits + key_bits; shift += kDigit) {
    std::fill(count.begin(), count.end(), 0u);
    const std::uint64_t mask = (std::uint64_t{1} << kDigit) - 1;
    for (const std::uint64_t k : keys) ++count[(k >> shift) & mask];
    std::uint32_t sum = 0;
    for (std::uint32_t& c : count) {
      const std::uint32_t here = c;
      c = sum;
      sum += here;
    }
    for (const std::uint64_t k : keys) buffer[count[(k >> shift) & mask]++] = k;
    keys.swap(buffer);
  }
  const std::uint64_t index_mask = (std::uint64_t{1} << index_bits) - 1;
  for (std::size_t r = 0; r < n; ++r) order[r] = static_cast<std::uint32_t>(keys[r] & index_mask);
  return order;
}

}  // namespace bccmis::d3::detail
