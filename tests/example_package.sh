#!/usr/bin/env bash
# Installs cellproj into a scratch prefix, builds examples/ against it with find_package(cellproj)
# as a user's project would, and runs the examples; imports the installed Python module.
# usage: example_package.sh BUILD_DIR SOURCE_DIR [PYTHON]
set -eu
build=$1; src=$2; python=${3:-}
prefix=$build/test-install; work=$build/test-example
rm -rf "$prefix" "$work"
cmake --install "$build" --prefix "$prefix" >/dev/null
cmake -S "$src/examples" -B "$work" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work" -j2 >/dev/null
"$work/solver_render" "$work/solver.png"
test -s "$work/solver.png" && test -s "$work/solver_step1.png"
# A solver links the render stack alone: no file-format library is loaded with it (docs/architecture.md).
formats=$(ldd "$work/solver_render" | grep -Ei 'vtk|netcdf|cgns|libtet' || true)
[ -z "$formats" ] || { echo "solver_render loads file-format libraries:"; echo "$formats"; exit 1; }
"$work/render_c" "$work/render_c.png"
# Only public headers are installed, and each compiles on its own against the installed tree.
inc=$prefix/include/cellproj
internal=$(find "$inc" -name '*.hpp' | grep -E 'cell_fragments|projected_|topology|split_sorter|ordered_pipeline|gl_' || true)
[ -z "$internal" ] || { echo "internal headers installed: $internal"; exit 1; }
for h in $(cd "$inc" && find . -name '*.hpp' | sed 's|^\./||'); do
  echo "#include \"$h\"" | c++ -std=c++17 -fsyntax-only -I"$inc" -x c++ - || { echo "$h does not compile alone"; exit 1; }
done
passed=4
if [ -n "$python" ] && [ -d "$prefix/lib/python3/dist-packages/cellproj" ]; then
  PYTHONPATH=$prefix/lib/python3/dist-packages "$python" -c "
import cellproj, sys
image = cellproj.render_scene(sys.argv[1], size=(32, 24))
assert image.shape == (24, 32, 4) and image[..., 3].max() > 0, image.shape
assert cellproj.__file__.startswith(sys.argv[2]), cellproj.__file__
" "$src/scenes/default.json" "$prefix"
  passed=$((passed + 1))
fi
echo "$passed passed, 0 failed"
