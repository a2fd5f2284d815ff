#!/usr/bin/env bash
# pt-linear's fan kernels side by side in one process (bench/fan_kernels.cpp), against this
# build's projection library: ns per pixel and the ratio to the AVX2 kernel, at a few tetrahedron
# sizes (the 1M box at 1024² is about 4).
# usage: bash bench/fan_kernels.sh [BUILD_DIR]
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath "${1:-$src/build}")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
g++ -O2 -std=c++17 -I"$src" -I"$build" "$src/bench/fan_kernels.cpp" -L"$build/lib" -lcellproj_projection \
  -lcellproj_view -lcellproj_optics -Wl,-rpath,"$build/lib" -o "$tmp/fan_kernels"
for spread in 2 4 8 16; do "$tmp/fan_kernels" $spread; done
