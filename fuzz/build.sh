#!/bin/bash -eu
# Builds the fuzz targets the way continuous fuzzing services (OSS-Fuzz,
# ClusterFuzzLite) expect: the compiler, flags and engine come from the
# environment, binaries and their side files go to $OUT.
#
#   CXX                 C++ compiler (clang++ for libFuzzer, afl-clang-fast++ for AFL++)
#   CXXFLAGS            instrumentation flags (-fsanitize=address,fuzzer-no-link ...)
#   LIB_FUZZING_ENGINE  engine link flags or library (-fsanitize=fuzzer, libAFLDriver.a ...)
#   OUT                 output directory
#   SRC                 optional; the checkout is found from this script's location
#
# For every target it writes $OUT/<target>, $OUT/<target>_seed_corpus.zip (from
# fuzz/corpus/<target>/), and $OUT/<target>.dict / .options when they exist.
# Only the core, the checker, the fast implementation, the 3D lattice and its
# checker, and tests/testing are compiled (no GTest, CLI11 or CGAL), so the
# build needs a C++20 compiler and GMP (libgmp-dev: the 3D mesh and its
# checker compute exact orientations with it).
#
# Local libFuzzer build:
#   CXX=clang++ CXXFLAGS="-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=all -g -O1" \
#   LIB_FUZZING_ENGINE=-fsanitize=fuzzer OUT=/tmp/fuzz-out fuzz/build.sh
# AFL++ build (see fuzz/README.md):
#   CXX=afl-clang-fast++ CXXFLAGS="-g -O1" LIB_FUZZING_ENGINE=-fsanitize=fuzzer \
#   AFL_USE_ASAN=1 AFL_USE_UBSAN=1 OUT=/tmp/afl-out fuzz/build.sh

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/.." && pwd)
: "${CXX:=clang++}"
: "${CXXFLAGS:=}"
: "${LIB_FUZZING_ENGINE:=-fsanitize=fuzzer}"
: "${OUT:?set OUT to the output directory}"
mkdir -p "$OUT"

work=$(mktemp -d "${WORK:-/tmp}/bccmis-fuzz-build.XXXXXX")
trap 'rm -rf "$work"' EXIT

includes=(-I"$root/src" -I"$root/tests" -I"$here")
# The libraries the targets link: the reference core, the checker (layers
# 1-4), the fast implementation, the 3D lattice (src/bccmis/d3) and its
# checker (src/bccmis/invariants/d3), and the shared test library (tests/testing:
# the lock-step twin, the byte programs). Compiled once, with the service's flags.
# (fuzz_conformance also needs the oracle library, whose page template CMake
# generates: it is built by the CMake fuzz preset only.)
objects=()
for source in "$root"/src/bccmis/*.cpp "$root"/src/bccmis/invariants/*.cpp "$root"/src/bccmis/fast/*.cpp \
              "$root"/src/bccmis/d3/*.cpp "$root"/src/bccmis/invariants/d3/*.cpp "$root"/tests/testing/*.cpp; do
  # <grandparent>_<parent>_<name>.o: d3/graph.cpp and graph.cpp must not collide.
  dir=$(dirname "$source")
  object="$work/$(basename "$(dirname "$dir")")_$(basename "$dir")_$(basename "$source" .cpp).o"
  # shellcheck disable=SC2086  # CXXFLAGS is a list of flags
  $CXX $CXXFLAGS -std=c++20 "${includes[@]}" -c "$source" -o "$object"
  objects+=("$object")
done
ar rcs "$work/libbccmis_fuzz.a" "${objects[@]}"

declare -A sources=(
  [fuzz_refine_coarsen]=refine_coarsen_fuzzer.cpp
  [fuzz_refine_coarsen_3d]=refine_coarsen_3d_fuzzer.cpp
  [fuzz_trace]=trace_fuzzer.cpp
  [fuzz_state]=state_fuzzer.cpp
  [fuzz_differential]=fuzz_differential.cpp
)
for target in "${!sources[@]}"; do
  # shellcheck disable=SC2086
  $CXX $CXXFLAGS -std=c++20 "${includes[@]}" "$here/${sources[$target]}" \
    "$work/libbccmis_fuzz.a" -lgmpxx -lgmp $LIB_FUZZING_ENGINE -o "$OUT/$target"
  if [ -d "$here/corpus/$target" ]; then
    rm -f "$OUT/${target}_seed_corpus.zip"
    (cd "$here/corpus/$target" && zip -q -r "$OUT/${target}_seed_corpus.zip" .)
  fi
  for ext in dict options; do
    if [ -f "$here/$target.$ext" ]; then cp "$here/$target.$ext" "$OUT/"; fi
  done
done
echo "built ${!sources[*]} into $OUT"
