#!/usr/bin/env bash
# What a mesh's cell numbering costs, and what renumbering the cells (mesh/cell_order.hpp) gives
# back, measured in one run: the 1M box (box-tets -n 55, bench/scenes/box_1m.json's view) as
# generated and with its cells shuffled (bench/shuffle_cells.py), rendered by A_EXE (a build
# without the renumbering, e.g. of the commit before it) and this build's cellproj in turn:
#  - frames: bench/ab_frames.sh, pt-linear and pt-breakpoints at 1024², exact and slicing at 512²
#    (the ray caster and slicing renumber too), ROUNDS rounds of 5 frames;
#  - one render from the command line (read, prepare, one frame, write), wall seconds, and the
#    prepare_seconds and the sort's phase of --stats, medians of ROUNDS runs each, A and B alternating.
# Results: bench/results/cell_numbering.txt; docs/methods.md, "Cell numbering".
# usage: [ROUNDS=3] bench/cell_numbering.sh A_EXE [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
a=$(realpath "$1"); b=$(realpath "${2:-build}/bin/cellproj"); rounds=${ROUNDS:-3}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
"$b" generate box-tets -n 55 -o "$work/ordered.vtu" >/dev/null
/usr/bin/python3 bench/shuffle_cells.py "$work/ordered.vtu" "$work/shuffled.vtu"
for m in ordered shuffled; do sed "s/box_1m.vtu/$m.vtu/" bench/scenes/box_1m.json >"$work/$m.json"; done
for m in ordered shuffled; do
  for method in pt-linear pt-breakpoints; do bash bench/ab_frames.sh "$a" "$b" "$work/$m.json" $method 1024 "$rounds" 5; done
  for method in exact slicing; do bash bench/ab_frames.sh "$a" "$b" "$work/$m.json" $method 512 "$rounds" 5; done
done
once() {  # EXE SCENE -> wall seconds, prepare seconds, whether renumbered (B only), sort seconds
  local start end
  start=$(date +%s.%N)
  "$1" render "$2" --size 1024x1024 --threads 2 --stats -o "$work/once.png" 2>"$work/once.err" >/dev/null
  end=$(date +%s.%N)
  tail -1 "$work/once.err" | python3 -c "import json, sys; s = json.load(sys.stdin)
print($end - $start, s['prepare_seconds'], s.get('cells_renumbered', '-'), s['phase_seconds']['sort'])"
}
for m in ordered shuffled; do
  log=$work/once_$m.txt
  for ((r = 0; r < rounds; r++)); do
    for x in $( ((r % 2 == 0)) && echo a b || echo b a); do echo "$x $(once "$([ $x = a ] && echo "$a" || echo "$b")" "$work/$m.json")" >>"$log"; done
  done
  python3 - "$m" "$log" <<'PY'
import statistics, sys
rows = [line.split() for line in open(sys.argv[2])]
med = lambda tag, k: statistics.median(float(r[k]) for r in rows if r[0] == tag)
renumbered = {r[3] for r in rows if r[0] == "b"}
print(f"{sys.argv[1]:9s} one render (pt-breakpoints, 1024²): wall A {med('a', 1):.2f} s  B {med('b', 1):.2f} s  "
      f"B/A {med('b', 1) / med('a', 1):.3f};  prepare A {med('a', 2):.2f} s  B {med('b', 2):.2f} s;  "
      f"sort A {med('a', 4):.3f} s  B {med('b', 4):.3f} s;  B renumbered: {','.join(sorted(renumbered))}")
PY
done
