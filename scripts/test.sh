#!/usr/bin/env bash
# The whole test suite: installs dependencies, then builds and runs ctest in
# the dev preset (g++, Debug, warnings as errors) and the asan preset (clang,
# address + undefined sanitizers, warnings as errors).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export CTEST_PARALLEL_LEVEL="${CTEST_PARALLEL_LEVEL:-2}"
export CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-2}"
for preset in dev asan; do
  echo "== preset $preset"
  cmake --workflow --preset "$preset"
done
