#!/usr/bin/env python3
"""The markdown table of docs/sorting.md from the CSV files bench/sorting.sh writes.

usage: python3 bench/sorting_table.py bench/results/sorting.csv [bench/results/sorting_1m.csv ...]
                                      [--times bench/results/sorting_times.csv]
With --times, the timing columns come from that run without the oracle (same meshes, sorts and
views), the relations and violations from the checked run.
"""
import csv
import os
import sys

COLUMNS = [("mesh", "mesh"), ("cells", "cells"), ("sort", "sort"), ("projection", "proj"),
           ("median_seconds", "median s"), ("min_seconds", "min s"), ("max_seconds", "max s"),
           ("cells_per_second", "cells/s"), ("face_relations", "face rel."), ("gap_relations", "gap rel."),
           ("pair_relations", "pair rel."), ("cycles", "cycles"), ("problem_cells", "problem cells")]
LEFT = {"mesh", "sort", "projection"}


TIMING = ("median_seconds", "min_seconds", "max_seconds", "cells_per_second")


def key(row):
    return os.path.basename(row["mesh"]), row["sort"], row["projection"]


def row_cells(row, times):
    timed = times.get(key(row), row)
    out = [os.path.basename(row["mesh"]) if k == "mesh" else (timed if k in TIMING else row).get(k, "") for k, _ in COLUMNS]
    violations = row.get("violations", "-")
    if violations in ("", "-"):
        out.append("not checked")
    else:
        clear = row.get("violating_pixels_without_overlap", "")
        out.append(f"{violations} ({row.get('violating_pixels', '')}" + (f"; {clear} without overlap)" if clear else ")"))
    return out


def main(args):
    times = {}
    if "--times" in args:
        at = args.index("--times")
        with open(args[at + 1], newline="") as f:
            times = {key(r): r for r in csv.DictReader(f)}
        args = args[:at] + args[at + 2:]
    print("| " + " | ".join(title for _, title in COLUMNS) + " | violations (pixels) |")
    print("| " + " | ".join("---" if k in LEFT else "---:" for k, _ in COLUMNS) + " | ---: |")
    for path in args:
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                print("| " + " | ".join(row_cells(row, times)) + " |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
