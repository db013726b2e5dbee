// bccmis-mpi stuff --animate --stats / --json: the frames' report rank 0
// prints (spec/distributed.md D17).
#pragma once

#include <cstdint>
#include <string>

#include "bccmis/distributed/animate_on_ranks.h"
#include "bccmis/json_writer.h"

namespace bccmis::cli {

/// D17's lines, a frame at a time, printed after the last frame.
class AnimateReport {
 public:
  /// With `compare`, each frame's scratch_seconds and the summary's
  /// mean_scratch_seconds and speedup.
  explicit AnimateReport(bool compare);
  /// Frame f, whose pieces hold `tetrahedra` in all.
  void add(const distributed::RankFrame& f, std::uint64_t tetrahedra);
  /// The text table, or with `json` the JSON object, with the summary.
  std::string finish(bool json);

 private:
  JsonWriter json_;
  std::string table_;
  bool compare_;
  double step_seconds_ = 0, scratch_seconds_ = 0;  ///< frames 1..N
  int steps_ = 0;
};

}  // namespace bccmis::cli
