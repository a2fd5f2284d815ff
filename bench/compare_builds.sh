#!/usr/bin/env bash
# Speed of two cellproj builds on the same scenes, measured in one run: each scene and method is
# rendered by A and B in turn (A, B, B, A, ... so drift favours neither), and the ratio of their
# median frame times is printed, with whether their pictures are bit-identical. For a refactor
# that must not change pictures or speed.
# usage: bench/compare_builds.sh A/bin/cellproj B/bin/cellproj [ROUNDS]   (about 4 minutes)
set -euo pipefail
a=$1; b=$2; rounds=${3:-3}
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
scenes=("$root/scenes/default.json")
for s in post_tets bluntfin static_mixer angular_sector; do
  [ -f "$root/../shared/data/README.md" ] && scenes+=("$root/bench/scenes/$s.json")
done
frame() {  # EXE SCENE METHOD OUT -> median frame seconds
  "$1" render "$2" --method "$3" --size 512x512 --frames 5 --npy "$4" -o "$tmp/x.png" --stats 2>&1 >/dev/null |
    tail -1 | python3 -c 'import json, sys; print(json.loads(sys.stdin.read())["frame_seconds"])'
}
printf '%-16s %-15s %9s %9s %7s %s\n' scene method "A s" "B s" "B/A" pictures
for s in "${scenes[@]}"; do
  for m in pt-table pt-breakpoints exact; do
    ta=(); tb=()
    for ((r = 0; r < rounds; r++)); do
      if ((r % 2 == 0)); then ta+=("$(frame "$a" "$s" $m "$tmp/a.npy")"); tb+=("$(frame "$b" "$s" $m "$tmp/b.npy")")
      else tb+=("$(frame "$b" "$s" $m "$tmp/b.npy")"); ta+=("$(frame "$a" "$s" $m "$tmp/a.npy")"); fi
    done
    same=$(cmp -s "$tmp/a.npy" "$tmp/b.npy" && echo identical || echo DIFFERENT)
    python3 - "$(basename "$s" .json)" $m "$same" "${ta[*]}" "${tb[*]}" <<'PY'
import statistics, sys
name, method, same, ta, tb = sys.argv[1:]
a = statistics.median(map(float, ta.split())); b = statistics.median(map(float, tb.split()))
print(f"{name:16s} {method:15s} {a:9.4f} {b:9.4f} {b / a:7.3f} {same}")
PY
  done
done
