#!/usr/bin/env bash
# The 1M box (box-tets -n 55 with bench/scenes/box_1m.json's camera and transfer function) at
# 1024² on 2 threads: VTK's projected tetrahedra mapper (bench/vtk_peer.py), then pt-linear and
# pt-breakpoints twice each, then VTK again, median of 5 frames each: the ratios of issue 21 in one
# run (bench/results/vtk_1m_final.txt). With A_EXE given, also bench/ab_frames.sh A_EXE against
# this build on the same scene.
# With SCENE set (a scene file, its mesh beside it: e.g. bench/run's DIR/meshes/tets-1m.json),
# that scene instead of the box.
# usage: [SCENE=scene.json] bench/vtk_1m.sh [BUILD_DIR] [A_EXE]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --bench  # Xvfb for VTK's mapper
exe=$(realpath "${1:-build}/bin/cellproj"); a=${2:-}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
scene=$work/scene.json
if [ -n "${SCENE:-}" ]; then
  scene=$(realpath "$SCENE")
else
  "$exe" generate box-tets -n 55 -o "$work/box_1m.vtu" >/dev/null
  cp bench/scenes/box_1m.json "$scene"
fi
peer() {
  xvfb-run -a /usr/bin/python3 bench/vtk_peer.py "$scene" --size 1024 --frames 5 --out "$work/peer" 2>/dev/null |
    tail -1 | python3 -c "import json, sys; print('vtk-pt median', json.load(sys.stdin)['median_seconds'])"
}
ours() {
  "$exe" render "$scene" --method "$1" --size 1024x1024 --frames 5 --threads 2 --stats -o "$work/o.png" 2>&1 |
    tail -1 | python3 -c "import json, sys; print('$1 median', json.load(sys.stdin)['frame_seconds'])"
}
peer; ours pt-linear; ours pt-breakpoints; ours pt-breakpoints; ours pt-linear; peer
if [ -n "$a" ]; then
  for m in pt-linear pt-breakpoints; do bash bench/ab_frames.sh "$a" "$exe" "$scene" $m 1024 5 4 | tail -1; done
fi
