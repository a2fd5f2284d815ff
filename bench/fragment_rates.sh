#!/usr/bin/env bash
# The projection methods' fragment rates (docs/methods.md, "Fragments" and "Threads"): on the
# 1M-tetrahedra box at 1024^2 (box-tets -n 55, the scene of bench/mpi.sh), 1 and 2 threads, 3 frames
# (median): frame seconds, ns per fragment, fragments per second, the fragments' memory traffic,
# and the seconds the ordered pipeline spent blending; then what this machine's memory copies.
# usage: bench/fragment_rates.sh [BUILD_DIR]   (about 2 minutes)
set -euo pipefail
build=${1:-build}
exe=$(realpath "$build/bin/cellproj")
py=${PYTHON:-/usr/bin/python3}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
# The 1M-tetrahedra box and its scene (bench/scenes/box_1m.json, shared with the other benchmarks).
"$exe" generate box-tets -n 55 -o "$work/box_1m.vtu" >/dev/null
cp "$(dirname "$0")/scenes/box_1m.json" "$work/box.json"
echo "| method | threads | frame s | ns per fragment | M fragments/s | fragment traffic GB/s | blend s |"
echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"
for m in pt-linear pt-table pt-analytic pt-breakpoints; do
  for t in 1 2; do
    "$exe" render "$work/box.json" --method $m --threads $t --frames 3 -o "$work/m.png" --stats 2>&1 >/dev/null |
      tail -1 | $py -c "import json, sys; j = json.load(sys.stdin)
traffic = j.get('fragment_traffic_gb_per_second')  # none with tiles: no fragment is stored
print('| $m | $t | %.2f | %.1f | %.1f | %s | %s |' % (j['frame_seconds'], j['ns_per_fragment'],
      j['fragments_per_second'] / 1e6, '%.1f' % traffic if traffic is not None else '-',
      '%.3f' % j['blend_seconds'] if j.get('blend_seconds') is not None else '-'))"
  done
done
$py - <<'PY'
import time
import numpy as np
a = np.ones(2**27)  # 1 GiB of doubles
b = np.empty_like(a)
best = max(2 * a.nbytes / t / 1e9 for t in [(lambda s: (np.copyto(b, a), time.perf_counter() - s)[1])(time.perf_counter()) for _ in range(3)])
print(f"memory copy, one thread (numpy): {best:.1f} GB/s read plus write")
PY
