#!/usr/bin/env bash
# The per-pixel closed form's cost (bench/closed_form.cpp) of optics/linear_segment.cpp as it is
# and as it was at REV, compiled side by side and run alternately, 3 times each.
# usage: bash bench/closed_form.sh [REV]    (default: 764412b, the recursion change that was reverted)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
rev=${1:-764412b}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
git -C "$src" show "$rev:optics/linear_segment.cpp" > "$tmp/old.cpp"
for v in old new; do
  file=$([ $v = old ] && echo "$tmp/old.cpp" || echo "$src/optics/linear_segment.cpp")
  g++ -O3 -DNDEBUG -std=c++17 -I"$src" "$src/bench/closed_form.cpp" "$file" "$src/optics/segment_integral.cpp" \
    "$src/optics/transfer_function.cpp" -o "$tmp/$v"
done
for r in 1 2 3; do
  for v in old new; do echo "$v ($([ $v = old ] && echo "$rev" || echo working tree)): $("$tmp/$v" | sed -E 's/ \([^)]*\)//' | tr '\n' ' ')"; done
done
