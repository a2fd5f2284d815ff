#!/usr/bin/env bash
# Installs cellproj into a scratch prefix, builds examples/ against it with find_package(cellproj)
# as a user's project would, and runs the example. usage: example_package.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1; src=$2
prefix=$build/test-install; work=$build/test-example
rm -rf "$prefix" "$work"
cmake --install "$build" --prefix "$prefix" >/dev/null
cmake -S "$src/examples" -B "$work" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work" -j2 >/dev/null
"$work/solver_render" "$work/solver.png"
test -s "$work/solver.png"
echo "1 passed, 0 failed"
