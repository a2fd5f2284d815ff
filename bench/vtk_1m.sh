#!/usr/bin/env bash
# The 1M box (box-tets -n 55 with bench/scenes/box_1m.json's camera and transfer function) at
# 1024² on 2 threads: VTK's projected tetrahedra mapper (bench/vtk_peer.py) beside pt-linear and
# pt-breakpoints, median of 5 frames each, in ROUNDS rounds (3; the order turned round every other
# round, so drift favours neither): the ratios of issue 21 per round, from runs made one after the
# other, then their median and range. This machine switches between two speeds minutes apart
# (docs/accuracy.md): a round's ratio compares runs made in the same state, and the median over
# rounds is what to quote (bench/results/vtk_1m_rounds.txt). With A_EXE given, also
# bench/ab_frames.sh A_EXE against this build on the same scene.
# With SCENE set (a scene file, its mesh beside it: e.g. bench/run's DIR/meshes/tets-1m.json),
# that scene instead of the box.
# usage: [SCENE=scene.json] [ROUNDS=3] bench/vtk_1m.sh [BUILD_DIR] [A_EXE]
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
    tail -1 | python3 -c "import json, sys; print(json.load(sys.stdin)['median_seconds'])"
}
ours() {
  "$exe" render "$scene" --method "$1" --size 1024x1024 --frames 5 --threads 2 --stats -o "$work/o.png" 2>&1 |
    tail -1 | python3 -c "import json, sys; print(json.load(sys.stdin)['frame_seconds'])"
}
log=$work/rounds.txt
for ((r = 1; r <= ${ROUNDS:-3}; r++)); do
  if ((r % 2)); then v=$(peer); l=$(ours pt-linear); b=$(ours pt-breakpoints)
  else b=$(ours pt-breakpoints); l=$(ours pt-linear); v=$(peer); fi
  echo "$r $v $l $b" >>"$log"
  python3 -c "import sys; r, v, l, b = sys.argv[1:]; v, l, b = map(float, (v, l, b))
print(f'round {r}: vtk-pt {v:.3f} s, pt-linear {l:.3f} s ({v / l:.2f}x), pt-breakpoints {b:.3f} s ({v / b:.2f}x)')" $r $v $l $b
done
python3 - "$log" <<'PY'
import statistics, sys
rows = [list(map(float, line.split()[1:])) for line in open(sys.argv[1])]
for k, m in ((1, "pt-linear"), (2, "pt-breakpoints")):
    x = [r[0] / r[k] for r in rows]
    print(f"{m}: median {statistics.median(x):.2f}x VTK over {len(x)} rounds (range {min(x):.2f}-{max(x):.2f}x)")
PY
if [ -n "$a" ]; then
  for m in pt-linear pt-breakpoints; do bash bench/ab_frames.sh "$a" "$exe" "$scene" $m 1024 5 4 | tail -1; done
fi
