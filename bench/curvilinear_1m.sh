#!/usr/bin/env bash
# Issue 5's target on a 1M-cell curvilinear hexahedral grid (the `swirl` ring, 210 x 70 x 70
# hexahedra with warped faces) at 1024^2 with 2 threads: whole-cell projection (--tetrahedralize
# problem, the default) against the same grid fully tetrahedralized (--tetrahedralize all) and
# rendered with pt-analytic; time per frame (3 frames, sort included) and the error of each against
# the exact renderer's isoparametric mode (and its canonical-tets mode) at 512^2; then one frame
# from a side view where faces fold (problem cells split).
# usage: bench/curvilinear_1m.sh [BUILD_DIR] [N]   (N=70: 1.03M cells; prints JSON lines)
set -euo pipefail
build=${1:-build}
n=${2:-70}
exe=$(realpath "$build/bin/cellproj")
here=$(dirname "$(realpath "$0")")  # before the cd below: a relative $0 would not resolve after it
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cd "$work"
bash "$here/swirl_scene.sh" . "$n" "$exe"
keys='("method", "tetrahedralize", "cells", "cells_projected", "problem_cells", "polyhedra", "polygons", "layered_polyhedra", "subdivisions_looked_up", "frame_seconds", "min_frame_seconds", "max_frame_seconds", "prepare_seconds")'
run() {  # name, then render options
  local name=$1; shift
  "$exe" render scene.json --size 1024x1024 --threads 2 --frames 3 -o "$name.png" --stats "$@" 2>&1 >/dev/null | tail -1 |
    python3 -c "import json, sys; j = json.load(sys.stdin); print(json.dumps(dict(run='$name', **{k: j.get(k) for k in $keys})))"
  "$exe" render scene.json --threads 2 --npy "$name.npy" -o "$name-512.png" "$@" >/dev/null 2>&1
}
run whole-breakpoints --method pt-breakpoints
run whole-analytic --method pt-analytic
run tets-analytic --method pt-analytic --tetrahedralize all
run tets-breakpoints --method pt-breakpoints --tetrahedralize all
"$exe" render scene.json --method exact --threads 2 --npy iso.npy -o iso.png >/dev/null 2>&1
"$exe" render scene.json --method exact --interpolation canonical-tets --threads 2 --npy ct.npy -o ct.png >/dev/null 2>&1
for r in whole-breakpoints whole-analytic tets-analytic tets-breakpoints; do
  echo "{\"run\": \"$r\", \"vs_isoparametric\": $("$exe" compare "$r.npy" iso.npy), \"vs_canonical_tets\": $("$exe" compare "$r.npy" ct.npy)}"
done
# A view along the ring's axis of symmetry folds faces: the sort phase of one frame there includes
# finding the problem cells and preparing the split mesh's topology and sorter.
sed 's/"eye": \[2.2, -2.8, 2.0\]/"eye": [3.5, 0.2, 0.3]/' scene.json > side.json
"$exe" render side.json --threads 2 -o side.png --stats 2>&1 >/dev/null | tail -1 |
  python3 -c "import json, sys; j = json.load(sys.stdin); print(json.dumps({'run': 'side-view', 'problem_cells': j['problem_cells'], 'sort_seconds': j['phase_seconds']['sort'], 'frame_seconds': j['frame_seconds']}))"
if [ -n "${KEEP:-}" ]; then cp ./*.png "$KEEP"/; fi
