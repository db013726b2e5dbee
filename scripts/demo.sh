#!/usr/bin/env bash
# The main job: build the CLI and replay the paper's Fig. 2 configuration
# with every invariant checked after every step (including the CGAL
# triangulation layer), printing the decision log, the canonical state and a
# summary.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh >&2
cmake --preset release >/dev/null
cmake --build --preset release --target bccmis >&2
trace="${1:-spec/examples/fig2.trace}"
./build/release/tools/bccmis/bccmis replay --check=every --depth=5 "$trace"
