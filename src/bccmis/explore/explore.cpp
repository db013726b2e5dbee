#include "bccmis/explore/explore.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/explore/detail/explorer.h"
#include "bccmis/invariants/invariants.h"

namespace bccmis {
namespace explore_detail {

// The 2D lattice: points (x, y), the checker's layers 1-4.
template <>
struct ExploreTraits<Graph> {
  static constexpr int dimension = 2;
  static std::array<std::int64_t, 2> coordinates(const Point& p) { return {p.x, p.y}; }
  static Point point(const std::array<std::int64_t, 2>& c) { return Point{c[0], c[1]}; }
  static std::array<std::int64_t, 2> extents(const LatticeSize& size) {
    const std::int64_t S = level0_side(size);
    return {size.W * S, size.H * S};
  }
  static std::vector<std::pair<const char*, std::int64_t>> size_fields(const LatticeSize& size) {
    return {{"W", size.W}, {"H", size.H}, {"L", size.L}};
  }
  static std::optional<std::string> violation(const Graph& g, int depth) {
    if (const auto v = find_violation(g, depth)) return to_string(*v);
    return std::nullopt;
  }
};

}  // namespace explore_detail

std::string encode_state_key(const Graph& g) { return explore_detail::encode_key(g); }

Graph decode_state_key(const std::string& key, const LatticeSize& size) {
  return explore_detail::decode_key<Graph>(key, size);
}

ExploreResult explore(const LatticeSize& size, const ExploreOptions& options) {
  validate_lattice_size(size);
  return explore_detail::Explorer<Graph>(size, options).run();
}

std::string summary(const ExploreResult& r) { return explore_detail::summary_of<Graph>(r); }

std::string to_json(const ExploreResult& r) { return explore_detail::json_of<Graph>(r); }

}  // namespace bccmis
