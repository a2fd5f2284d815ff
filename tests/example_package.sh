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
test -s "$work/solver.png" && test -s "$work/solver_step1.png"
# Only public headers are installed, and each compiles on its own against the installed tree.
inc=$prefix/include/cellproj
internal=$(find "$inc" -name '*.hpp' | grep -E 'cell_fragments|projected_|topology|split_sorter|ordered_pipeline|gl_' || true)
[ -z "$internal" ] || { echo "internal headers installed: $internal"; exit 1; }
for h in $(cd "$inc" && find . -name '*.hpp' | sed 's|^\./||'); do
  echo "#include \"$h\"" | c++ -std=c++17 -fsyntax-only -I"$inc" -x c++ - || { echo "$h does not compile alone"; exit 1; }
done
echo "2 passed, 0 failed"
