#!/usr/bin/env bash
# Whole-cell projection on the shared curvilinear datasets (bench/scenes: Blunt Fin, combustion
# chamber; needs ../shared/data): per scene, the default (--tetrahedralize problem) against every
# cell split (--tetrahedralize all), both pt-breakpoints, 2 threads, median of 3 frames (the camera
# turns 1 degree a frame); problem cells, the fast path's share of whole cells, and each picture's
# error against exact (isoparametric) at the scene's own size.
# usage: bench/whole_cells.sh [BUILD_DIR]   (prints JSON lines)
set -euo pipefail
build=${1:-build}
exe=$(realpath "$build/bin/cellproj")
scenes=$(cd "$(dirname "$0")/scenes" && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
for name in bluntfin combustion_chamber; do
  scene=$scenes/$name.json
  for mode in problem all; do
    "$exe" render "$scene" --threads 2 --frames 3 --tetrahedralize $mode -o "$work/$mode.png" --stats 2>&1 >/dev/null |
      tail -1 > "$work/$mode.json"
    "$exe" render "$scene" --threads 2 --tetrahedralize $mode --npy "$work/$mode.npy" -o "$work/$mode.png" >/dev/null 2>&1
  done
  "$exe" render "$scene" --method exact --threads 2 --npy "$work/iso.npy" -o "$work/iso.png" >/dev/null 2>&1
  python3 - "$name" "$work" "$("$exe" compare "$work/problem.npy" "$work/iso.npy")" \
    "$("$exe" compare "$work/all.npy" "$work/iso.npy")" <<'PY'
import json, sys
name, work, whole_err, tets_err = sys.argv[1:5]
w = json.load(open(f"{work}/problem.json"))
t = json.load(open(f"{work}/all.json"))
print(json.dumps({"scene": name, "size": f"{w['width']}x{w['height']}", "cells": w["cells"],
                  "problem_cells": w["problem_cells"], "polyhedra": w["polyhedra"],
                  "looked_up_share": round(w["subdivisions_looked_up"] / max(1, w["polyhedra"]), 4),
                  "whole_seconds": w["frame_seconds"], "tets_seconds": t["frame_seconds"],
                  "whole_vs_isoparametric": json.loads(whole_err), "tets_vs_isoparametric": json.loads(tets_err)}))
PY
done
