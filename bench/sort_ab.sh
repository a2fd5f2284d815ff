#!/usr/bin/env bash
# The mpvo sort's phases in two cellproj builds, measured in one run: `cellproj sortbench` of every
# mesh by A and B in turn (A, B, B, A, ... so drift favours neither), 24 views, one thread (THREADS); per
# mesh the median over the rounds of each phase (face_relations, topological_sort) and of the
# whole sort, with B/A. For judging a change to the sort on this noisy machine.
# usage: [ROUNDS=3] [VIEWS=24] [THREADS=1] bench/sort_ab.sh A_EXE B_EXE MESH...
set -euo pipefail
a=$1; b=$2; shift 2
rounds=${ROUNDS:-3}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for ((r = 0; r < rounds; r++)); do
  for x in $( ((r % 2 == 0)) && echo a b || echo b a); do
    "$([ $x = a ] && echo "$a" || echo "$b")" sortbench "$@" --sorts mpvo --views "${VIEWS:-24}" \
      --threads "${THREADS:-1}" --json 2>/dev/null >>"$tmp/$x.jsonl"
  done
done
python3 - "$tmp/a.jsonl" "$tmp/b.jsonl" <<'PY'
import json, statistics, sys
from collections import defaultdict
runs = []
for f in sys.argv[1:]:
    by = defaultdict(lambda: defaultdict(list))
    for line in open(f):
        d = json.loads(line)
        by[d["mesh"]]["sort"].append(d["median_seconds"])
        for k, v in d["phase_seconds"].items():
            by[d["mesh"]][k].append(v)
    runs.append(by)
a, b = runs
print("%-28s %-17s %9s %9s %6s" % ("mesh", "phase", "A s", "B s", "B/A"))
for mesh in a:
    for phase in ("face_relations", "topological_sort", "sort"):
        ma, mb = statistics.median(a[mesh][phase]), statistics.median(b[mesh][phase])
        print("%-28s %-17s %9.5f %9.5f %6.3f" % (mesh.split("/")[-1][-28:], phase, ma, mb, mb / ma))
PY
