#!/usr/bin/env bash
# pt-linear's fan kernels side by side in one process (bench/fan_kernels.cpp, built in BUILD_DIR
# by bench/build.sh against its projection library): ns per pixel and the ratio to the AVX2 kernel, at a few tetrahedron
# sizes (the 1M box at 1024² is about 4).
# usage: bash bench/fan_kernels.sh [BUILD_DIR]
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath "${1:-$src/build}")
bin=$(bash "$src/bench/build.sh" "$build" bench_fan_kernels)
for spread in 2 4 8 16; do "$bin/bench_fan_kernels" $spread; done
