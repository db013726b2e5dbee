#include "bccmis/apps/moving_disk.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

#include "bccmis/apps/detail/generic.h"

namespace bccmis {

bool cell_meets_disk(const LatticeSize& size, const Point& center, int level, const Disk& d) {
  const double half = static_cast<double>(cell_side(size, level)) / 2;
  const double dx = std::max(std::abs(d.x - static_cast<double>(center.x)) - half, 0.0);
  const double dy = std::max(std::abs(d.y - static_cast<double>(center.y)) - half, 0.0);
  return dx * dx + dy * dy <= d.radius * d.radius;
}

AdaptReport adapt_to_disks(Graph& g, std::span<const Disk> disks, int target_level, Balance balance) {
  return detail::adapt_to_disks(g, disks, target_level, balance);
}

AdaptReport adapt_to_disks(fast::Lattice& g, std::span<const Disk> disks, int target_level, Balance balance) {
  return detail::adapt_to_disks(g, disks, target_level, balance);
}

std::vector<std::array<double, 2>> parse_path(std::string_view text) {
  std::vector<std::array<double, 2>> path;
  auto trim = [](std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
  };
  auto number = [&](std::string_view s, std::string_view point, double& out) {
    s = trim(s);
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
    if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(out))
      throw std::invalid_argument("path point " + std::to_string(path.size() + 1) + " '" + std::string(point) + "': '" +
                                  std::string(s) + "' is not a number");
  };
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const std::string_view point = trim(text.substr(start, end - start));
    const std::size_t comma = point.find(',');
    if (comma == std::string_view::npos)
      throw std::invalid_argument("path point " + std::to_string(path.size() + 1) + " '" + std::string(point) +
                                  "': expected x,y");
    std::array<double, 2> p{};
    number(point.substr(0, comma), point, p[0]);
    number(point.substr(comma + 1), point, p[1]);
    path.push_back(p);
    start = end + 1;
  }
  return path;
}

std::array<double, 2> point_on_path(const std::vector<std::array<double, 2>>& path, double t) {
  if (path.empty()) return {0, 0};
  std::vector<double> length(path.size(), 0.0);
  for (std::size_t i = 1; i < path.size(); ++i)
    length[i] = length[i - 1] + std::hypot(path[i][0] - path[i - 1][0], path[i][1] - path[i - 1][1]);
  const double want = std::clamp(t, 0.0, 1.0) * length.back();
  for (std::size_t i = 1; i < path.size(); ++i)
    if (want <= length[i] && length[i] > length[i - 1]) {
      const double f = (want - length[i - 1]) / (length[i] - length[i - 1]);
      return {path[i - 1][0] + f * (path[i][0] - path[i - 1][0]), path[i - 1][1] + f * (path[i][1] - path[i - 1][1])};
    }
  return path.back();
}

}  // namespace bccmis
