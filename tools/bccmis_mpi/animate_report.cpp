// spec/distributed.md D17: the frames of bccmis-mpi stuff --animate as
// --stats (a table) and --json (an object) print them.
#include "animate_report.h"

namespace bccmis::cli {

AnimateReport::AnimateReport()
    : table_("frame coarsened refined corrections imbalance repartitioned leaves tetrahedra seconds\n") {
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
      .member("seconds", f.seconds)
      .end_object();
  table_ += std::to_string(f.index) + " " + std::to_string(s.coarsened) + " " + std::to_string(s.refined) + " " +
            std::to_string(s.corrections) + " " + JsonWriter::number(s.imbalance) + " " +
            (s.repartitioned ? "1" : "0") + " " + std::to_string(f.leaves) + " " + std::to_string(tetrahedra) + " " +
            JsonWriter::number(f.seconds) + "\n";
  if (f.index > 0) {
    step_seconds_ += f.seconds;
    ++steps_;
  }
}

std::string AnimateReport::finish(bool json) {
  const double mean = steps_ > 0 ? step_seconds_ / steps_ : 0;
  if (json) return json_.end_array().member("mean_step_seconds", mean).end_object().str() + "\n";
  return table_ + "mean_step_seconds " + JsonWriter::number(mean) + "\n";
}

}  // namespace bccmis::cli
