#!/usr/bin/env bash
# Thread scaling of the projection methods (docs/methods.md, "Threads and Amdahl"): each scene,
# method and thread count rendered RUNS times (2), 4 frames each at 1024², with `--stats`; per run
# the fastest and median frame and the phases (the sort, the order-free passes beside it, the
# tiles' own orders when they ran, project and composite). Extra render options after `--` apply
# to every run (e.g. `-- --tile-orders on`).
# usage: [RUNS=2] [THREADS="1 2"] [METHODS="pt-linear pt-breakpoints"] bench/threads.sh EXE SCENE... [-- options]
set -euo pipefail
exe=$1; shift
scenes=()
while (($#)) && [ "$1" != "--" ]; do scenes+=("$1"); shift; done
(($#)) && shift
extra=("$@")
py=${PYTHON:-/usr/bin/python3}
for scene in "${scenes[@]}"; do
  for m in ${METHODS:-pt-linear pt-breakpoints}; do
    for t in ${THREADS:-1 2}; do
      for ((run = 1; run <= ${RUNS:-2}; run++)); do
        "$exe" render "$scene" --method "$m" --size 1024x1024 --frames 4 --threads "$t" --stats -o /dev/null \
          "${extra[@]}" 2>&1 >/dev/null | tail -1 | $py -c "
import json, sys
d = json.loads(sys.stdin.read()); ph = d['phase_seconds']
print('%s %s threads %s run %d: fastest %.3f median %.3f, order %s, sort %.4f, passes %.4f, tile orders %s, project and composite %.3f'
      % ('$(basename "$scene" .json)', '$m', '$t', $run, d['min_frame_seconds'], d['frame_seconds'], d['visibility_order'],
         ph['sort'], ph.get('small cells', 0), '%.4f' % ph['tile orders'] if 'tile orders' in ph else '-',
         ph['project and composite']))"
      done
    done
  done
done
