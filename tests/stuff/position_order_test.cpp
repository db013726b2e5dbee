// The numbering's order by position (spec/stuffing.md S8a): the radix sort
// of packed keys against std::sort of the points, on random distinct points
// with narrow coordinate ranges (the radix path, digits of every width) and
// with ranges too wide to pack (the fallback), negative coordinates included.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "bccmis/d3/detail/position_order.h"

namespace bccmis::d3::detail {
namespace {

/// n distinct points with coordinates in [low, low + span) on each axis.
std::vector<d3::Point> random_points(std::size_t n, std::int64_t low, std::int64_t span, std::mt19937_64& rng) {
  std::uniform_int_distribution<std::int64_t> coordinate(low, low + span - 1);
  std::set<d3::Point> seen;
  std::vector<d3::Point> points;
  while (points.size() < n) {
    const d3::Point p{coordinate(rng), coordinate(rng), coordinate(rng)};
    if (seen.insert(p).second) points.push_back(p);
  }
  return points;
}

/// The expected order, computed independently of S8a's packing.
std::vector<std::uint32_t> sorted_order(const std::vector<d3::Point>& points) {
  std::vector<std::uint32_t> order(points.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return points[a] < points[b]; });
  return order;
}

//= spec/stuffing.md S8a type=test
TEST(PositionOrder, RadixSortEqualsStdSortOnRandomPoints) {
  std::mt19937_64 rng(29);
  // Spans from 2 (1 bit an axis, one pass) to 2^20 (60 key bits plus the
  // index's: the fallback), offsets negative and positive.
  for (const std::int64_t span : {2LL, 3LL, 17LL, 64LL, 1000LL, 1LL << 13, 1LL << 20})
    for (const std::int64_t low : {0LL, -5LL, 123456789LL})
      for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{5}, std::size_t{3000}}) {
        if (static_cast<double>(n) > static_cast<double>(span * span * span)) continue;
        const auto points = random_points(n, low, span, rng);
        EXPECT_EQ(position_order(points), sorted_order(points)) << "span " << span << " low " << low << " n " << n;
      }
}

//= spec/stuffing.md S8a type=test
TEST(PositionOrder, ExtremeCoordinatesTakeTheFallback) {
  std::vector<d3::Point> points{{INT64_MAX, 0, 0}, {INT64_MIN, 1, 0}, {0, 0, 0}, {0, -1, 7}, {0, -1, INT64_MIN}};
  EXPECT_EQ(position_order(points), sorted_order(points));
}

}  // namespace
}  // namespace bccmis::d3::detail
