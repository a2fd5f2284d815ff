#!/usr/bin/env bash
# Where a frame of the 1M box goes (docs/methods.md, "Where a frame goes"): each method's frame,
# then cut short before each cell's rasterizing (CELLPROJ_STOP_AT=cells: the sort, binning, the
# small cells' count and each tetrahedron's projection are left) and before shading any pixel
# (=runs: the rasterizer walks every run). Needs a build with bench/frame_phases.patch applied:
#   git apply bench/frame_phases.patch && cmake --build build && bash bench/frame_phases.sh build
#   git apply -R bench/frame_phases.patch && cmake --build build
# usage: bench/frame_phases.sh [BUILD_DIR] [ROUNDS=2]   (1024², 2 threads, fastest of 4 frames)
set -euo pipefail
cd "$(dirname "$0")/.."
exe=$(realpath "${1:-build}/bin/cellproj"); rounds=${2:-2}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
"$exe" generate box-tets -n 55 -o "$work/box_1m.vtu" >/dev/null
cp bench/scenes/box_1m.json "$work/scene.json"
for method in pt-linear pt-breakpoints; do
  for ((r = 0; r < rounds; r++)); do
    for stop in frame cells runs; do
      CELLPROJ_STOP_AT=$stop "$exe" render "$work/scene.json" --method "$method" --size 1024x1024 --threads 2 \
        --frames 4 -o "$work/o.png" --stats 2>&1 >/dev/null | tail -1 |
        python3 -c "import json, sys; j = json.load(sys.stdin); print('$method', '$stop', j['min_frame_seconds'])"
    done
  done
done
