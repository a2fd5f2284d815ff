#!/usr/bin/env bash
# Builds benchmark programs of bench/CMakeLists.txt in BUILD_DIR (switching CELLPROJ_BUILD_BENCH on
# there; the libraries they link are the build's own) and prints BUILD_DIR/bin.
# usage: bench/build.sh BUILD_DIR TARGET... [-- CMAKE_OPTION...]
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$1; shift
targets=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do targets+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCELLPROJ_BUILD_BENCH=ON "$@" >/dev/null
cmake --build "$build" -j"$(nproc)" --target "${targets[@]}" >/dev/null
echo "$(cd "$build" && pwd)/bin"
