#!/usr/bin/env bash
# Frame time of two cellproj builds on one scene, measured in one run: A and B render in turn
# (A, B, B, A, ... so drift favours neither), each FRAMES frames on THREADS threads (2), and the median of
# their per-run median frame times is printed with the ratio B/A, then the fastest frame of each
# over all runs and their ratio (steadier on this machine), and whether the last pictures
# are bit-identical (if not, their largest difference, with numpy). For judging one change on
# this noisy machine, where only side-by-side runs tell tens of percent.
# usage: [THREADS=2] bench/ab_frames.sh A_EXE B_EXE SCENE METHOD SIZE [ROUNDS=3] [FRAMES=4] [-- extra render options]
#   A_EXE: e.g. a build of the previous commit (git worktree add /tmp/a REV; cmake -S /tmp/a -B
#   /tmp/a/build -DCMAKE_BUILD_TYPE=Release; cmake --build /tmp/a/build --target cellproj).
set -euo pipefail
a=$1; b=$2; scene=$3; method=$4; size=$5; shift 5
rounds=3; frames=4
if [ $# -gt 0 ] && [ "$1" != "--" ]; then rounds=$1; shift; fi
if [ $# -gt 0 ] && [ "$1" != "--" ]; then frames=$1; shift; fi
[ "${1:-}" = "--" ] && shift; extra=("$@")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
frame() {  # EXE TAG -> median and fastest frame seconds of the run
  "$1" render "$scene" --method "$method" --size "${size}x${size}" --frames "$frames" --threads "${THREADS:-2}" -o "$tmp/$2.png" \
    --npy "$tmp/$2.npy" --stats "${extra[@]}" 2>"$tmp/$2.err" >/dev/null
  tail -1 "$tmp/$2.err" | python3 -c 'import json, sys; s = json.load(sys.stdin); print(s["frame_seconds"], s["min_frame_seconds"])'
}
ta=(); tb=(); fa=(); fb=()
for ((r = 0; r < rounds; r++)); do
  for x in $( ((r % 2 == 0)) && echo a b || echo b a); do
    read -r med fast < <(frame "$([ $x = a ] && echo "$a" || echo "$b")" $x)
    if [ $x = a ]; then ta+=("$med"); fa+=("$fast"); else tb+=("$med"); fb+=("$fast"); fi
  done
done
same=identical
if ! cmp -s "$tmp/a.npy" "$tmp/b.npy"; then  # how far apart: the largest difference and how many values
  same=$(${PYTHON:-/usr/bin/python3} -c 'import sys, numpy as np
a, b = (np.load(f).astype(float) for f in sys.argv[1:]); d = np.abs(a - b)
print("DIFFERENT (largest %.2g in %d of %d values)" % (d.max(), (d > 0).sum(), d.size))' "$tmp/a.npy" "$tmp/b.npy" ||
    echo DIFFERENT)
fi
python3 - "$(basename "$scene" .json)" "$method" "$size" "$same" "${ta[*]}" "${tb[*]}" "${fa[*]}" "${fb[*]}" <<'PY'
import statistics, sys
name, method, size, same, ta, tb, fa, fb = sys.argv[1:]
a = statistics.median(map(float, ta.split())); b = statistics.median(map(float, tb.split()))
# The fastest frame of all runs: the least disturbed by the machine's neighbours.
fa = min(map(float, fa.split())); fb = min(map(float, fb.split()))
print(f"{name:14s} {method:15s} {size}²  A {a:.3f} s  B {b:.3f} s  B/A {b / a:.3f}  "
      f"fastest A {fa:.3f} B {fb:.3f} B/A {fb / fa:.3f}  {same}")
PY
