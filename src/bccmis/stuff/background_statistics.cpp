// S13a's statistics on their own threads (background_statistics.h).
#include "bccmis/stuff/background_statistics.h"

namespace bccmis::stuff {

BackgroundStatistics::BackgroundStatistics(const d3::TetMeshF& mesh, int threads)
    : vertices_(mesh.vertices), tets_(mesh.tets) {
  thread_ = std::jthread([this, threads] {
    try {
      quality_ = quality(vertices_, tets_, 0, threads);
    } catch (...) {
      error_ = std::current_exception();
    }
  });
}

Statistics BackgroundStatistics::finish(const Shape& shape, const std::vector<std::array<std::uint32_t, 3>>& boundary,
                                        bool hausdorff) {
  thread_.join();
  if (error_) std::rethrow_exception(error_);
  return statistics(shape, quality_, vertices_, tets_.size(), boundary, hausdorff);
}

}  // namespace bccmis::stuff
