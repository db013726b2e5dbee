// SoupReport's names and summary (soup_report.h).
#include "bccmis/stuff/soup_report.h"

namespace bccmis::stuff {

const char* SoupReport::key(Kind k) {
  switch (k) {
    case degenerate_faces: return "degenerate_faces";
    case duplicate_faces: return "duplicate_faces";
    case back_to_back_faces: return "back_to_back_faces";
    case nonmanifold_edges: return "nonmanifold_edges";
    case border_edges: return "border_edges";
    case inconsistent_edges: return "inconsistent_edges";
    case nonmanifold_vertices: return "nonmanifold_vertices";
    case self_intersections: return "self_intersecting_pairs";
    case kKinds: break;
  }
  return "?";
}

std::size_t SoupReport::flaw_count() const {
  std::size_t n = 0;
  for (const auto& f : flaws) n += f.count;
  return n;
}

std::string SoupReport::summary() const {
  static const char* const words[kKinds][2] = {{"degenerate face", "degenerate faces"},
                                               {"duplicate face", "duplicate faces"},
                                               {"back-to-back face pair", "back-to-back face pairs"},
                                               {"non-manifold edge", "non-manifold edges"},
                                               {"border edge", "border edges"},
                                               {"inconsistently oriented edge", "inconsistently oriented edges"},
                                               {"non-manifold vertex", "non-manifold vertices"},
                                               {"self-intersecting face pair", "self-intersecting face pairs"}};
  std::string out;
  for (std::size_t k = 0; k < kKinds; ++k) {
    const std::size_t n = flaws[k].count;
    if (n == 0) continue;
    out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + words[k][n == 1 ? 0 : 1];
  }
  return out;
}

}  // namespace bccmis::stuff
