// What every bench/ program's main() shares: its own --bccmis_* flags are
// taken out of argv, the rest goes to Google Benchmark.
#pragma once

#include <benchmark/benchmark.h>

#include <string_view>

namespace bccmis::bench {

/// Removes from argv (after argv[0]) every argument that `take(arg)`
/// accepts by returning true; the others keep their order.
template <class Take>
void take_flags(int& argc, char** argv, const Take& take) {
  int kept = 1;
  for (int i = 1; i < argc; ++i)
    if (!take(std::string_view(argv[i]))) argv[kept++] = argv[i];
  argc = kept;
}

/// Google Benchmark's main on the remaining arguments: runs the registered
/// benchmarks; 1 when an argument is not one of its flags.
inline int run_benchmarks(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace bccmis::bench
