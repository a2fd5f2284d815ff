#!/usr/bin/env bash
# Compositing by image tiles against the ordered stream of fragments (docs/methods.md, "Tiles"),
# side by side in one run (bench/ab_frames.sh, A = --compositing stream, B = tiles, 2 threads, the
# pictures compared bit for bit): the 1M-tetrahedra box at 1024² (4 methods), the 1M-hexahedra
# swirl at 1024² (whole cells), tets-10k at 1024²; then tiles on 1 and 2 threads (the speed-up), and
# the straddle (visits per cell) of 16-, 32- and 64-row tiles; the 1- and 2-thread lines give the
# sort's serial share and the phase speed-up that docs/methods.md's Amdahl figures come from.
# usage: bench/tiles.sh [BUILD_DIR] [ROUNDS=4]   (about 8 minutes)
set -euo pipefail
cd "$(dirname "$0")/.."
exe=$(realpath "${1:-build}/bin/cellproj"); rounds=${2:-4}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
for c in stream tiles; do printf '#!/bin/sh\nexec %s "$@" --compositing %s\n' "$exe" $c >"$work/$c"; chmod +x "$work/$c"; done
"$exe" generate box-tets -n 55 -o "$work/box_1m.vtu" >/dev/null
cp bench/scenes/box_1m.json "$work/box_1m.json"
"$exe" generate box-tets -n 12 -o "$work/tets_10k.vtu" >/dev/null
sed 's/box_1m.vtu/tets_10k.vtu/' bench/scenes/box_1m.json >"$work/tets_10k.json"
bash bench/swirl_scene.sh "$work/swirl" 70 "$exe" >/dev/null
ab() { bash bench/ab_frames.sh "$work/stream" "$work/tiles" "$@" "$rounds" 4; }
echo "A = stream, B = tiles (B/A < 1: tiles faster)"
for m in pt-linear pt-table pt-analytic pt-breakpoints; do ab "$work/box_1m.json" $m 1024; done
for m in pt-linear pt-breakpoints; do ab "$work/swirl/scene.json" $m 1024; done
for m in pt-linear pt-breakpoints; do ab "$work/tets_10k.json" $m 1024; done
echo "tiles, 1 and 2 threads (1M box, 1024², 3 frames, median):"
for m in pt-linear pt-breakpoints; do
  for t in 1 2; do
    "$exe" render "$work/box_1m.json" --method $m --threads $t --frames 3 -o "$work/t.png" --stats 2>&1 >/dev/null |
      tail -1 | python3 -c "import json, sys; j = json.load(sys.stdin)
p = j['phase_seconds']
print('$m threads $t: %.3f s (sort %.3f s, project and composite %.3f s), %d tiles, %.3f visits per cell' % (
      j['frame_seconds'], p['sort'], p['project and composite'], j['tiles'], j['tile_visits'] / j['cells']))"
  done
done
echo "tile height against straddle (1M box, 1024², pt-linear, 1 frame):"
for rows in 16 32 64; do
  "$exe" render "$work/box_1m.json" --method pt-linear --threads 2 --tile-rows $rows -o "$work/t.png" --stats 2>&1 >/dev/null |
    tail -1 | python3 -c "import json, sys; j = json.load(sys.stdin)
print('$rows rows: %d tiles, %.3f visits per cell, %.3f s' % (j['tiles'], j['tile_visits'] / j['cells'], j['frame_seconds']))"
done
