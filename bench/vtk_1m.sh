#!/usr/bin/env bash
# The 1M box (box-tets -n 55 with bench/scenes/box_1m.json's camera and transfer function) at
# 1024² on 2 threads: VTK's projected tetrahedra mapper (bench/vtk_peer.py) beside each projection
# rung (pt-linear, pt-table, pt-analytic, pt-breakpoints), median of 5 frames each, in ROUNDS rounds
# (3; the order turned round every other round, so drift favours neither): the ratios of issue 21
# and each rung's ns per fragment per round, from runs made one after the other, then their
# median and range. This machine switches between two speeds minutes apart
# (docs/accuracy.md): a round's ratio compares runs made within a minute or so, mostly in one
# state; its slow state slows ours more than VTK's mapper, so rounds in it show lower ratios.
# Quote the median with the range (bench/results/vtk_1m_rounds.txt). With A_EXE given, also
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
ours() {  # frame seconds and ns per fragment
  "$exe" render "$scene" --method "$1" --size 1024x1024 --frames 5 --threads 2 --stats -o "$work/o.png" 2>&1 |
    tail -1 | python3 -c "import json, sys; j = json.load(sys.stdin); print(j['frame_seconds'], j['ns_per_fragment'])"
}
methods=(pt-linear pt-table pt-analytic pt-breakpoints)
log=$work/rounds.txt
for ((r = 1; r <= ${ROUNDS:-3}; r++)); do
  declare -A t=()
  if ((r % 2)); then order=(vtk "${methods[@]}"); else order=(pt-breakpoints pt-analytic pt-table pt-linear vtk); fi
  for m in "${order[@]}"; do if [ $m = vtk ]; then t[$m]=$(peer); else t[$m]=$(ours $m); fi; done
  line="$r ${t[vtk]}"
  for m in "${methods[@]}"; do line+=" $m ${t[$m]}"; done
  echo "$line" >>"$log"
  python3 - $line <<'PY'
import sys
a = sys.argv[1:]; v = float(a[1])
rungs = [f"{a[k]} {float(a[k + 1]):.3f} s ({v / float(a[k + 1]):.2f}x, {float(a[k + 2]):.1f} ns/fragment)"
         for k in range(2, len(a), 3)]
print(f"round {a[0]}: vtk-pt {v:.3f} s; " + ", ".join(rungs))
PY
done
python3 - "$log" <<'PY'
import statistics, sys
rows = [line.split() for line in open(sys.argv[1])]
for k in range(2, len(rows[0]), 3):
    x = [float(r[1]) / float(r[k + 1]) for r in rows]
    ns = statistics.median(float(r[k + 2]) for r in rows)
    print(f"{rows[0][k]}: median {statistics.median(x):.2f}x VTK over {len(x)} rounds "
          f"(range {min(x):.2f}-{max(x):.2f}x), {ns:.1f} ns/fragment")
PY
if [ -n "$a" ]; then
  for m in pt-linear pt-breakpoints; do bash bench/ab_frames.sh "$a" "$exe" "$scene" $m 1024 5 4 | tail -1; done
fi
