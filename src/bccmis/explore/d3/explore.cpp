// bccmis::d3 explore: the 3D exhaustive explorer declared in explore.h (this
// folder holds the 3D counterpart of src/bccmis/explore/), over the 2D
// explorer's machinery in explore/detail/explorer.h.
#include "bccmis/explore/d3/explore.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/d3/mesh.h"
#include "bccmis/explore/detail/explorer.h"
#include "bccmis/invariants/d3/invariants.h"

namespace bccmis {
namespace explore_detail {

// The 3D lattice: points (x, y, z), the 3D checker's layers 1-4 and, with all
// four, the mesh layer on the lattice's own tetrahedra.
template <>
struct ExploreTraits<d3::Graph> {
  static constexpr int dimension = 3;
  static std::array<std::int64_t, 3> coordinates(const d3::Point& p) { return {p.x, p.y, p.z}; }
  static d3::Point point(const std::array<std::int64_t, 3>& c) { return d3::Point{c[0], c[1], c[2]}; }
  static std::array<std::int64_t, 3> extents(const d3::LatticeSize& size) {
    const std::int64_t S = d3::level0_side(size);
    return {size.W * S, size.H * S, size.D * S};
  }
  static std::vector<std::pair<const char*, std::int64_t>> size_fields(const d3::LatticeSize& size) {
    return {{"W", size.W}, {"H", size.H}, {"D", size.D}, {"L", size.L}};
  }
  static std::optional<std::string> violation(const d3::Graph& g, int depth) {
    if (const auto v = d3::find_violation(g, depth)) return to_string(*v);
    if (depth < 4) return std::nullopt;
    std::vector<d3::Tet> tets;
    try {
      tets = d3::tetrahedra(g);
    } catch (const std::exception& e) {
      return std::string("mesh: tetrahedra(g) threw: ") + e.what();
    }
    if (const auto v = d3::check_mesh(g, tets)) return to_string(*v);
    return std::nullopt;
  }
};

}  // namespace explore_detail

namespace d3 {

std::string encode_state_key(const d3::Graph& g) { return explore_detail::encode_key(g); }

d3::Graph decode_state_key(const std::string& key, const d3::LatticeSize& size) {
  return explore_detail::decode_key<d3::Graph>(key, size);
}

d3::ExploreResult explore(const d3::LatticeSize& size, const d3::ExploreOptions& options) {
  d3::validate_lattice_size(size);
  return explore_detail::Explorer<d3::Graph>(size, options).run();
}

std::string summary(const d3::ExploreResult& r) { return explore_detail::summary_of<d3::Graph>(r); }

std::string to_json(const d3::ExploreResult& r) { return explore_detail::json_of<d3::Graph>(r); }

}  // namespace d3
}  // namespace bccmis
