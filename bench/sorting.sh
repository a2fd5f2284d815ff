#!/usr/bin/env bash
# The table of docs/sorting.md: every sort on the synthetic meshes and on every dataset of
# ../shared/data, 8 views, orthographic and perspective, checked by the order oracle. The sorts
# are timed in a run of their own (the oracle between two timed sorts would evict their caches).
# usage: bash bench/sorting.sh [BUILD_DIR] [OUT_DIR]     (about 5 minutes on 2 cores)
# table: python3 bench/sorting_table.py OUT_DIR/sorting.csv OUT_DIR/sorting_1m.csv --times OUT_DIR/sorting_times.csv
set -euo pipefail
build=${1:-build}; out=${2:-bench/results}
exe=$build/bin/cellproj
source "$(dirname "$0")/shared_data.sh"
mkdir -p "$out"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$exe" generate box-tets -n 12 -o "$tmp/box-tets-10k.vtu" >/dev/null
"$exe" generate swirl-tets -n 8 -o "$tmp/swirl-tets-9k.vtu" >/dev/null
"$exe" generate swirl -n 12 -o "$tmp/swirl-hex-5k.vtu" >/dev/null
"$exe" generate mixed -n 10 -o "$tmp/mixed-3k.vtu" >/dev/null
meshes=("$tmp"/*.vtu)
mapfile -t -O ${#meshes[@]} meshes < <(shared_meshes)
"$exe" sortbench "${meshes[@]}" --views 8 --size 512x512 --projection both --pairwise-limit 20000 \
  --csv "$out/sorting_times.csv" > "$out/sorting_times.txt"
"$exe" sortbench "${meshes[@]}" --views 8 --size 512x512 --projection both --check --pairwise-limit 20000 \
  --csv "$out/sorting.csv" | tee "$out/sorting.txt"
# The 1M-tetrahedra targets: mpvo against the centroid radix sort in the same run.
"$exe" generate box-tets -n 56 -o "$tmp/box-tets-1m.vtu" >/dev/null
"$exe" sortbench "$tmp/box-tets-1m.vtu" --views 8 --size 1024x1024 --projection both --sorts centroid,mpvo,mpvo-abuffer \
  --csv "$out/sorting_1m.csv" | tee "$out/sorting_1m.txt"
