// spec/distributed.md D15, step 3: the imbalance and the threshold.
#include "bccmis/distributed/repartition.h"

#include <algorithm>

namespace bccmis::distributed {

namespace {

struct Counts {
  double largest = 0, total = 0, ranks = 0;
};

Counts counts(std::span<const std::int64_t> leaves) {
  Counts c;
  for (const std::int64_t n : leaves) {
    c.largest = std::max(c.largest, static_cast<double>(n));
    c.total += static_cast<double>(n);
  }
  c.ranks = static_cast<double>(leaves.size());
  return c;
}

}  // namespace

double imbalance(std::span<const std::int64_t> leaves) {
  const Counts c = counts(leaves);
  return c.total > 0 ? c.largest * c.ranks / c.total : 1.0;
}

bool repartition_needed(std::span<const std::int64_t> leaves, double threshold) {
  const Counts c = counts(leaves);
  // D15: repartitioned when max_r n_r P > t N; at I = t exactly, not.
  return c.largest * c.ranks > threshold * c.total;
}

}  // namespace bccmis::distributed
