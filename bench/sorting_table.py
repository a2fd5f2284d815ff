#!/usr/bin/env python3
"""The markdown table of docs/sorting.md from the CSV files bench/sorting.sh writes.

usage: python3 bench/sorting_table.py bench/results/sorting.csv [bench/results/sorting_1m.csv ...]
"""
import csv
import os
import sys

COLUMNS = [("mesh", "mesh"), ("cells", "cells"), ("sort", "sort"), ("projection", "proj"),
           ("median_seconds", "median s"), ("min_seconds", "min s"), ("max_seconds", "max s"),
           ("cells_per_second", "cells/s"), ("face_relations", "face rel."), ("gap_relations", "gap rel."),
           ("pair_relations", "pair rel."), ("cycles", "cycles"), ("problem_cells", "problem cells")]
LEFT = {"mesh", "sort", "projection"}


def row_cells(row):
    out = [os.path.basename(row["mesh"]) if key == "mesh" else row.get(key, "") for key, _ in COLUMNS]
    violations = row.get("violations", "-")
    out.append("not checked" if violations in ("", "-") else f"{violations} ({row.get('violating_pixels', '')})")
    return out


def main(paths):
    print("| " + " | ".join(title for _, title in COLUMNS) + " | violations (pixels) |")
    print("| " + " | ".join("---" if key in LEFT else "---:" for key, _ in COLUMNS) + " | ---: |")
    for path in paths:
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                print("| " + " | ".join(row_cells(row)) + " |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
