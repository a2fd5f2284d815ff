#!/usr/bin/env bash
# What a fresh array costs to fill in 4 KB pages and in huge pages (bench/fresh_pages.cpp), and the
# machine's transparent huge page settings, which decide whether the advice is taken.
# usage: bash bench/fresh_pages.sh [ELEMENTS]    (default 6M int64: 48 MB; BUILD_DIR=build)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
bin=$(bash "$src/bench/build.sh" "${BUILD_DIR:-$src/build}" bench_fresh_pages)
echo "THP enabled: $(cat /sys/kernel/mm/transparent_hugepage/enabled 2>/dev/null || echo unknown)"
echo "THP defrag:  $(cat /sys/kernel/mm/transparent_hugepage/defrag 2>/dev/null || echo unknown)"
"$bin/bench_fresh_pages" "$@"
