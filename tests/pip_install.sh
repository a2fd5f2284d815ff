#!/usr/bin/env bash
# `pip install .` as a Python user runs it (pyproject.toml), offline with Debian's pip, setuptools and
# wheel, into a fresh folder: the installed module needs none of the build's libraries, and renders
# the CLI's picture of the default mesh bit for bit.
# usage: pip_install.sh SOURCE_DIR CELLPROJ PYTHON        (a few minutes: the module's CMake build)
set -euo pipefail
src=$1; exe=$2; python=$3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/src"
# The clone's files only (pip builds in the tree it is given; the CMake build folders stay out).
(cd "$src" && git ls-files -z | xargs -0 cp --parents -t "$tmp/src")
CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-2} \
  "$python" -m pip install --quiet --no-build-isolation --no-deps --target "$tmp/site" "$tmp/src" >"$tmp/pip.log" 2>&1 ||
  { cat "$tmp/pip.log"; echo "FAIL: pip install"; exit 1; }
module=$(ls "$tmp"/site/cellproj/_cellproj*.so)
if ldd "$module" | grep -q libcellproj; then echo "FAIL: the installed module links the build's libraries"; exit 1; fi
"$exe" render "$src/scenes/default.vtu" --colormap viridis --view +x --size 64x48 --npy "$tmp/cli.npy" -o "$tmp/cli.png" >/dev/null
cd "$tmp" && PYTHONPATH="$tmp/site" "$python" - "$tmp/cli.npy" "$src/scenes/default.vtu" "$tmp/site" <<'PY'
import sys
import numpy as np
import cellproj
assert cellproj.__file__.startswith(sys.argv[3]), "imported %s, not the installed package" % cellproj.__file__
image = cellproj.render(sys.argv[2], cmap="viridis", view="+x", size=(64, 48))
assert np.array_equal(image, np.load(sys.argv[1])), "the installed module's picture differs from the CLI's"
print("pip install: the installed cellproj renders the CLI's picture bit for bit")
PY
