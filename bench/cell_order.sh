#!/usr/bin/env bash
# The cost of renumbering a mesh's cells (bench/cell_order.cpp, built in BUILD_DIR by bench/build.sh):
# numbering_spread, morton_cell_order and a whole LocalCells copy, and CGAL's hilbert_sort of the
# same centroids, medians of RUNS calls, on the 1M box as generated and shuffled
# (bench/shuffle_cells.py). docs/methods.md, "Cell numbering".
# usage: [RUNS=5] bash bench/cell_order.sh [BUILD_DIR]
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath "${1:-$src/build}")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
bin=$(bash "$src/bench/build.sh" "$build" bench_cell_order cellproj)
"$bin/cellproj" generate box-tets -n 55 -o "$tmp/ordered.vtu" >/dev/null
/usr/bin/python3 "$src/bench/shuffle_cells.py" "$tmp/ordered.vtu" "$tmp/shuffled.vtu"
for m in ordered shuffled; do "$bin/bench_cell_order" "$tmp/$m.vtu" "${RUNS:-5}"; done
