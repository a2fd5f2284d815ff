#!/usr/bin/env bash
# Speed of two cellproj builds on the same scenes, measured in one run: each scene and method is
# rendered by A and B in turn (A, B, B, A, ... so drift favours neither), and the ratio of their
# median frame times is printed, with whether their pictures are bit-identical. For a refactor
# that must not change pictures or speed. Then every other path (each method, sort, back end,
# tetrahedralize mode, interpolation, --frames, slicing's families, integrals and back
# ends) at 96x80, compared bit for bit.
# usage: bench/compare_builds.sh A/bin/cellproj B/bin/cellproj [ROUNDS]   (about 5 minutes)
set -euo pipefail
a=$1; b=$2; rounds=${3:-3}
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
scenes=("$root/scenes/default.json")
for s in post_tets bluntfin static_mixer angular_sector; do
  [ -f "$root/../shared/data/README.md" ] && scenes+=("$root/bench/scenes/$s.json")
done
for s in "${scenes[@]}"; do
  for m in pt-table pt-breakpoints exact; do
    bash "$root/bench/ab_frames.sh" "$a" "$b" "$s" $m 512 "$rounds" 5
  done
done

paths=("--method pt-linear" "--method pt-analytic" "--method exact --interpolation canonical-tets"
       "--tetrahedralize all" "--tetrahedralize none" "--sort centroid" "--sort mpvo" "--sort mpvo-abuffer"
       "--sort pairwise" "--method pt-table --backend opengl" "--method pt-table --backend opengl-8bit"
       "--method pt-table --backend opengl-8bit-dither" "--frames 3 --threads 1"
       "--method slicing --slices 64" "--method slicing --slices 200 --slice-integral sampled"
       "--method slicing --slices 128 --slice-axis view" "--method slicing --slices 96 --tetrahedralize all --slice-axis x"
       "--method slicing --slices 50 --tetrahedralize none --slice-integral sampled"
       "--method slicing --slices 64 --slice-integral sampled --backend opengl-8bit-dither")
same=0; differ=0
for s in "${scenes[@]}"; do
  for p in "${paths[@]}"; do
    # shellcheck disable=SC2086  # each path is a list of options
    "$a" render "$s" --size 96x80 $p --npy "$tmp/a.npy" -o "$tmp/x.png" >/dev/null 2>&1 || echo "A failed: $s $p"
    "$b" render "$s" --size 96x80 $p --npy "$tmp/b.npy" -o "$tmp/x.png" >/dev/null 2>&1 || echo "B failed: $s $p"
    if cmp -s "$tmp/a.npy" "$tmp/b.npy"; then same=$((same + 1)); else differ=$((differ + 1)); echo "DIFFERENT: $(basename "$s") $p"; fi
  done
done
echo "other paths at 96x80: $same bit-identical, $differ different"
