// spec/distributed.md D17: the frames of bccmis-mpi stuff --animate as
// --stats (a table) and --json (an object) print them.
#include "animate_report.h"

#include <string>

namespace bccmis::cli {

AnimateReport::AnimateReport(bool compare)
    : table_("frame coarsened refined corrections imbalance repartitioned leaves tetrahedra seconds" +
             std::string(compare ? " scratch_seconds" : "") + "\n"),
      compare_(compare) {
  json_.begin_object().key("frames").begin_array();
}

void AnimateReport::add(const distributed::RankFrame& f, std::uint64_t tetrahedra) {
  const distributed::ForestStep& s = f.step;
  json_.begin_object()
      .member("frame", f.index)
      .member("coarsened", s.coarsened)
      .member("refined", s.refined)
      .member("corrections", s.corrections)
      .member("imbalance", s.imbalance)
      .member("repartitioned", s.repartitioned)
      .member("leaves", f.leaves)
      .member("tetrahedra", tetrahedra)
      .member("seconds", f.seconds);
  if (compare_) json_.member("scratch_seconds", f.scratch_seconds);
  json_.end_object();
  table_ += std::to_string(f.index) + " " + std::to_string(s.coarsened) + " " + std::to_string(s.refined) + " " +
            std::to_string(s.corrections) + " " + JsonWriter::number(s.imbalance) + " " +
            (s.repartitioned ? "1" : "0") + " " + std::to_string(f.leaves) + " " + std::to_string(tetrahedra) + " " +
            JsonWriter::number(f.seconds) + (compare_ ? " " + JsonWriter::number(f.scratch_seconds) : "") + "\n";
  if (f.index > 0) {
    step_seconds_ += f.seconds;
    scratch_seconds_ += f.scratch_seconds;
    ++steps_;
  }
}

std::string AnimateReport::finish(bool json) {
  const double mean = steps_ > 0 ? step_seconds_ / steps_ : 0;
  const double scratch = steps_ > 0 ? scratch_seconds_ / steps_ : 0;
  const double speedup = mean > 0 ? scratch / mean : 0;  // as the serial AnimationSummary::speedup()
  json_.end_array().member("mean_step_seconds", mean);
  std::string table = table_ + "mean_step_seconds " + JsonWriter::number(mean) + "\n";
  if (compare_) {
    json_.member("mean_scratch_seconds", scratch).member("speedup", speedup);
    table += "mean_scratch_seconds " + JsonWriter::number(scratch) + "\nspeedup " + JsonWriter::number(speedup) + "\n";
  }
  return json ? json_.end_object().str() + "\n" : table;
}

}  // namespace bccmis::cli
