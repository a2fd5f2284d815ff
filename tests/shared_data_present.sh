#!/usr/bin/env bash
# Counts the datasets of ../shared/data that the tests read; exit 77 (ctest: skipped) without it.
# usage: shared_data_present.sh DATA_DIR
dir=$1
if [ ! -d "$dir" ]; then
  echo "no $dir beside this clone: every test on the shared datasets is skipped"
  exit 77
fi
n=$(find "$dir" -mindepth 1 -maxdepth 1 -type d | wc -l)
echo "$n dataset folders in $dir"
[ "$n" -gt 0 ] || exit 77
