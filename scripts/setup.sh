#!/usr/bin/env bash
# Installs the Debian 12 packages bccmis needs (idempotent; fast when they are
# already installed). Run as root, or with sudo available.
set -euo pipefail

packages=(
  cmake ninja-build g++ clang-14 clang-format-14 libclang-rt-14-dev llvm-14 pkg-config python3 git
  libgtest-dev libgmock-dev googletest librapidcheck-dev libbenchmark-dev
  libcgal-dev libgmp-dev libmpfr-dev libcli11-dev libstb-dev
  # the zlib-compressed .vtu (spec/mesh3d.md M20)
  zlib1g-dev
  # CGAL's sample meshes (data.tar.gz) for the surface loader's tests (tests/stuff/stuff.cmake)
  libcgal-demo
  # outside readers of the 3D mesh writers (tests/d3/mesh_readers_test.py)
  python3-meshio gmsh
  # the winding-number volume of tests/stuff/wild_files_test.py and bench/stuff_wild.py
  python3-numpy
  # the Python module (python/, spec/python.md) and its tests (tests/python/, pytest; matplotlib for
  # the README's example)
  pybind11-dev python3-pybind11 python3-dev python3-pytest python3-matplotlib
  # the peers of `bccmis stuff` in the comparison benchmark (bench/stuff_peers.cpp)
  tetgen
  # peak memory and CPU seconds of a run in bench/replay_e2e.sh (also its smoke test)
  time
  # optional components: the p4est bridge (p4est is built with OpenMPI, whose
  # headers libp4est-dev does not pull in) and the browser test of the viewer
  libp4est-dev libopenmpi-dev openmpi-bin chromium
)

missing=()
for p in "${packages[@]}"; do
  if [ "$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null)" != "installed" ]; then
    missing+=("$p")
  fi
done
if [ "${#missing[@]}" -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "setup: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
# clang++ is clang 14 on Debian 12; make sure the unversioned name exists.
if ! command -v clang++ >/dev/null 2>&1; then
  $sudo ln -sf /usr/bin/clang++-14 /usr/local/bin/clang++
  $sudo ln -sf /usr/bin/clang-14 /usr/local/bin/clang
fi
echo "setup: done"
