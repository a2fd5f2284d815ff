#!/usr/bin/env bash
# Targets on a 1M-tetrahedron mesh (a 56^3 box, 6 tetrahedra per cube): topology (`info`) in ~2 s
# and the exact renderer at 512^2 in ~2 min (foundation issue); cell projection at 1024^2 with 2
# threads in at most 1 s per frame, sort included (issue 4): pt-linear and pt-table, 5 frames.
# usage: bench/exact_1m.sh [BUILD_DIR]   (prints the timings as JSON lines)
set -euo pipefail
build=${1:-build}
exe=$build/bin/cellproj
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
"$exe" generate box-tets -n 56 -o "$work/box.vtu"
"$exe" info "$work/box.vtu" --json | python3 -c '
import json, sys; j = json.load(sys.stdin)
print(json.dumps({k: j[k] for k in ("cells", "read_seconds", "topology_seconds", "boundary_faces", "convex")}))'
cat > "$work/scene.json" <<JSON
{ "mesh": "box.vtu", "field": "scalar",
  "transfer_function": { "color": [[0, 0.2, 0.3, 0.9], [0.6, 0.9, 0.8, 0.3], [1, 1, 0.3, 0.1]],
                         "extinction": [[0, 0.2], [0.6, 1.0], [0.8, 4.0], [1, 8.0]] },
  "camera": { "projection": "perspective", "eye": [3.5, 2.5, 4.5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 35 },
  "image": { "width": 512, "height": 512 } }
JSON
"$exe" render "$work/scene.json" --method exact -o "$work/box.png" --stats 2>&1 >/dev/null | tail -1
for m in pt-linear pt-table; do
  "$exe" render "$work/scene.json" --method "$m" --size 1024x1024 --threads 2 --frames 5 -o "$work/$m.png" --stats 2>&1 >/dev/null |
    tail -1 | python3 -c 'import json, sys; j = json.load(sys.stdin)
print(json.dumps({k: j[k] for k in ("method", "cells", "width", "height", "threads", "frame_seconds", "min_frame_seconds", "max_frame_seconds")}))'
done
