#!/usr/bin/env bash
# The cost of renumbering a mesh's cells (bench/cell_order.cpp against this build's grid library):
# numbering_spread, morton_cell_order and a whole LocalCells copy, and CGAL's hilbert_sort of the
# same centroids, medians of RUNS calls, on the 1M box as generated and shuffled
# (bench/shuffle_cells.py). docs/methods.md, "Cell numbering".
# usage: [RUNS=5] bash bench/cell_order.sh [BUILD_DIR]
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath "${1:-$src/build}")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
g++ -O2 -std=c++17 -I"$src" -I"$build" "$src/bench/cell_order.cpp" -L"$build/lib" -lcellproj_grid -ltbb \
  -Wl,-rpath,"$build/lib" -o "$tmp/cell_order"
"$build/bin/cellproj" generate box-tets -n 55 -o "$tmp/ordered.vtu" >/dev/null
/usr/bin/python3 "$src/bench/shuffle_cells.py" "$tmp/ordered.vtu" "$tmp/shuffled.vtu"
for m in ordered shuffled; do "$tmp/cell_order" "$tmp/$m.vtu" "${RUNS:-5}"; done
