// Work split into contiguous ranges, one per thread (spec/stuffing.md S28):
// for per-item work whose result does not depend on the split.
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace bccmis::stuff::detail {

/// The threads a run uses: `threads`, or every core when it is 0 (at least 1).
inline int thread_count(int threads) {
  return threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

/// The ranges for_each_part cuts n items into: `threads` (0: every core),
/// fewer when a range would hold fewer than `least` items, at least 1.
inline std::size_t part_count(std::size_t n, int threads, std::size_t least) {
  return std::max<std::size_t>(
      1, std::min(static_cast<std::size_t>(thread_count(threads)), n / std::max<std::size_t>(least, 1)));
}

/// f(k, begin, end) over [0, n) cut into part_count(n, threads, least)
/// contiguous ranges k = 0, 1, ..., each on its own thread, the first on the
/// calling thread. The first range's exception in range order is rethrown
/// once all have ended.
template <class F>
void for_each_part(std::size_t n, int threads, std::size_t least, F&& f) {
  const std::size_t parts = part_count(n, threads, least);
  if (parts == 1) {
    f(std::size_t{0}, std::size_t{0}, n);
    return;
  }
  std::vector<std::exception_ptr> errors(parts);
  const auto run = [&](std::size_t k) {
    try {
      f(k, n * k / parts, n * (k + 1) / parts);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  };
  std::vector<std::thread> helpers;
  for (std::size_t k = 1; k < parts; ++k) helpers.emplace_back(run, k);
  run(0);
  for (std::thread& t : helpers) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

/// f(begin, end): for_each_part without the range's number.
template <class F>
void for_each_range(std::size_t n, int threads, std::size_t least, F&& f) {
  for_each_part(n, threads, least, [&f](std::size_t, std::size_t b, std::size_t e) { f(b, e); });
}

}  // namespace bccmis::stuff::detail
