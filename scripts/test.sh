#!/usr/bin/env bash
# The whole test suite: installs dependencies, then configures, builds and
# runs ctest in four workflows:
#   dev         g++, Debug, warnings as errors: every default test
#   asan        clang, address + undefined sanitizers, warnings as errors: every default test
#   exhaustive  g++ Release: every reachable state of lattices 3 1 2, 2 2 2 and 1 1 3
#   fuzz        clang + libFuzzer + sanitizers: a 30 s campaign per fuzz target
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export CTEST_PARALLEL_LEVEL="${CTEST_PARALLEL_LEVEL:-2}"
export CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-2}"
for preset in dev asan exhaustive fuzz; do
  echo "== workflow $preset"
  start=$(date +%s)
  cmake --workflow --preset "$preset"
  echo "== workflow $preset passed in $(( $(date +%s) - start )) s"
done
