// S25's estimate of a run's memory (memory_estimate.h).
#include "bccmis/stuff/memory_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace bccmis::stuff {

namespace {

/// The level-L cubes of the fitted lattice: an upper bound of the leaves.
double all_cubes(const Fit& fit) {
  return static_cast<double>(fit.size.W) * static_cast<double>(fit.size.H) * static_cast<double>(fit.size.D) *
         std::ldexp(1.0, 3 * fit.size.L);
}

std::string gigabytes(double bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g GB", bytes / 1e9);
  return buf;
}

}  // namespace

MemoryEstimate estimate_memory(const Shape& shape, const StuffOptions& options, double available_bytes, int meshes) {
  const Fit fit = fit_lattice(shape.bounds(), options);
  MemoryEstimate e;
  e.meshes = meshes;
  e.leaves = all_cubes(fit);
  if (e.bytes() <= available_bytes) return e;
  // S25: the probe, at the smallest level P >= 2 with N 2^P > 10, when below L.
  int P = 2;
  while (std::ldexp(static_cast<double>(options.cells), P) <= 10) ++P;
  if (P >= fit.size.L) return e;
  StuffOptions probe = options;
  probe.size.reset();
  probe.max_level = P;
  probe.min_level = std::min(options.min_level, P);
  const Fit coarse = fit_lattice(shape.bounds(), probe);
  const double probe_leaves = static_cast<double>(background_fast(shape, coarse, probe).cell_count());
  // Every leaf at least --min-level deep: the initial cubes times 8^min-level.
  const double floor = static_cast<double>(fit.size.W) * static_cast<double>(fit.size.H) *
                       static_cast<double>(fit.size.D) * std::ldexp(1.0, 3 * options.min_level);
  e.leaves = std::min(e.leaves, std::max(floor, probe_leaves * std::ldexp(1.0, 2 * (fit.size.L - P))));
  return e;
}

std::optional<double> available_memory() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024;
  return std::nullopt;
}

int coarsest_max_level(const StuffOptions& options) {
  int level = std::max(options.min_level, 0);
  while (level < 20 && std::ldexp(static_cast<double>(options.cells), level) <= 10) ++level;  // S2: N 2^L > 10
  return level;
}

std::string too_much_memory(int level, double leaves, double bytes, double available_bytes, const std::string& whose,
                            const std::string& how, const std::string& for_whom, int coarsest) {
  // The finest level that fits: the estimate falls by 4 (at least) a level;
  // never below the coarsest level the options allow (S25).
  int fits = level;
  double b = bytes;
  for (; fits > coarsest && b > available_bytes; b /= 4) --fits;
  char count[32];
  std::snprintf(count, sizeof count, "%.3g", leaves);
  const std::string level_hint = b > available_bytes ? "even -L " + std::to_string(coarsest) +
                                                           ", the coarsest max level these options allow, would not fit"
                                                     : "-L " + std::to_string(fits) + " would fit";
  return "max level " + std::to_string(level) + " needs about " + count + " leaves, " + gigabytes(bytes) + " " + whose +
         " (" + how + "), more than the " + gigabytes(available_bytes) + " of memory available" + for_whom + "; " +
         level_hint;
}

void refuse_what_will_not_fit(const Shape& shape, const StuffOptions& options, double available_bytes, int meshes) {
  const Fit fit = fit_lattice(shape.bounds(), options);
  const MemoryEstimate e = estimate_memory(shape, options, available_bytes, meshes);
  if (e.bytes() <= available_bytes) return;
  throw ShapeError(too_much_memory(
      fit.size.L, e.leaves, e.bytes(), available_bytes, "by S25's estimate",
      std::to_string(static_cast<int>(kBytesPerLeaf)) + " bytes per estimated leaf" +
          (meshes > 1
               ? ", and " + std::to_string(static_cast<int>(kSecondMeshBytesPerLeaf)) + " for S35.8's second mesh"
               : std::string()),
      "", coarsest_max_level(options)));
}

}  // namespace bccmis::stuff
