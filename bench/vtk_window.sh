#!/usr/bin/env bash
# The mapper's frame time in a VTK window at 1M tetrahedra, 1024² (the box of bench/vtk_1m.sh),
# against the CLI's frame time and VTK's projected tetrahedra in the same run (issue 60).
# usage: bench/vtk_window.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(realpath "${1:-build}")
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
"$build/bin/cellproj" generate box-tets -n 55 -o "$work/box_1m.vtu" >/dev/null
cp bench/scenes/box_1m.json "$work/scene.json"
PYTHONPATH=$build/python xvfb-run -a /usr/bin/python3 bench/vtk_window.py "$work/scene.json" "$build/bin/cellproj" "${@:2}"
