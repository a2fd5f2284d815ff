#!/usr/bin/env bash
# What a fresh array costs to fill in 4 KB pages and in huge pages (bench/fresh_pages.cpp), and the
# machine's transparent huge page settings, which decide whether the advice is taken.
# usage: bash bench/fresh_pages.sh [ELEMENTS]    (default 6M int64: 48 MB)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
g++ -O2 -std=c++17 -I"$src" "$src/bench/fresh_pages.cpp" -o "$tmp/fresh_pages"
echo "THP enabled: $(cat /sys/kernel/mm/transparent_hugepage/enabled 2>/dev/null || echo unknown)"
echo "THP defrag:  $(cat /sys/kernel/mm/transparent_hugepage/defrag 2>/dev/null || echo unknown)"
"$tmp/fresh_pages" "$@"
