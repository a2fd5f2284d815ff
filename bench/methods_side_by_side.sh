#!/usr/bin/env bash
# Frame times of several methods of one build on one scene, measured in one run: each round renders
# every method once (FRAMES frames, 2 threads), the order turned by one each round so that drift
# favours none; printed per method: the median of its per-run median frame times, its fastest
# frame, and both against the first method's. For placing methods against each other on this noisy
# machine (docs/accuracy.md's "Choosing"), where separate runs minutes apart do not tell 10%.
# usage: bench/methods_side_by_side.sh EXE SCENE SIZE ROUNDS FRAMES METHOD... [-- extra render options]
set -euo pipefail
exe=$1 scene=$2 size=$3 rounds=$4 frames=$5; shift 5
methods=(); while [ $# -gt 0 ] && [ "$1" != "--" ]; do methods+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift; extra=("$@")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
n=${#methods[@]}
for ((r = 0; r < rounds; r++)); do
  for ((k = 0; k < n; k++)); do
    m=${methods[$(((k + r) % n))]}
    "$exe" render "$scene" --method "$m" --size "${size}x${size}" --frames "$frames" --threads 2 -o "$tmp/$m.png" \
      --stats "${extra[@]}" 2>"$tmp/err" >/dev/null || { echo "$m failed:" >&2; tail -3 "$tmp/err" >&2; exit 1; }
    tail -1 "$tmp/err" | ${PYTHON:-/usr/bin/python3} -c 'import json, sys; s = json.load(sys.stdin)
print(s["frame_seconds"], s["min_frame_seconds"])' >>"$tmp/$m.times"
  done
done
${PYTHON:-/usr/bin/python3} - "$scene" "$size" "$tmp" "${methods[@]}" <<'PY'
import os, statistics, sys
scene, size, tmp, methods = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
rows = []
for m in methods:
    t = [tuple(map(float, line.split())) for line in open(os.path.join(tmp, m + ".times"))]
    rows.append((m, statistics.median(x[0] for x in t), min(x[1] for x in t)))
print(f"{os.path.basename(scene)} {size}², {len(t)} rounds")
for m, med, fast in rows:
    print(f"  {m:<16} median {med:.3f} s  fastest {fast:.3f} s  /{rows[0][0]}: {med / rows[0][1]:.2f} {fast / rows[0][2]:.2f}")
PY
