#!/usr/bin/env bash
# The per-pixel closed form's cost (bench/closed_form.cpp) of optics/linear_segment.cpp as it is
# and as it was at REV, compiled side by side and run alternately, 3 times each; then the largest
# relative difference of their weights over 2M segments of the series region (closed_form --dump),
# after each one's error on small cells against long double quadrature (closed_form --accuracy).
# Both are bench_closed_form (bench/CMakeLists.txt), built in a scratch folder: _a from the working
# tree, _b from REV's file.
# usage: bash bench/closed_form.sh [REV]    (default: 764412b, the recursion change that was reverted)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
rev=${1:-764412b}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
git -C "$src" show "$rev:optics/linear_segment.cpp" > "$tmp/old.cpp"
bin=$(bash "$src/bench/build.sh" "$tmp/build" bench_closed_form_a bench_closed_form_b -- \
  -DCELLPROJ_BENCH_LINEAR_SEGMENT_B="$tmp/old.cpp" -DCELLPROJ_BUILD_TESTS=OFF -DCELLPROJ_PYTHON=OFF)
ln -s "$bin/bench_closed_form_b" "$tmp/old"; ln -s "$bin/bench_closed_form_a" "$tmp/new"
for r in 1 2 3; do
  for v in old new; do echo "$v ($([ $v = old ] && echo "$rev" || echo working tree)): $("$tmp/$v" | sed -E 's/ \([^)]*\)//' | tr '\n' ' ')"; done
done
for v in old new; do echo "$v: $("$tmp/$v" --accuracy)"; done
"$tmp/old" --dump > "$tmp/old.txt"; "$tmp/new" --dump > "$tmp/new.txt"
python3 - "$tmp/old.txt" "$tmp/new.txt" <<'PY'
import sys
worst, n = [0.0, 0.0], 0
with open(sys.argv[1]) as fa, open(sys.argv[2]) as fb:
    for la, lb in zip(fa, fb):
        n += 1
        for k, (x, y) in enumerate(zip(map(float, la.split()), map(float, lb.split()))):
            worst[k] = max(worst[k], abs(x - y) / max(abs(x), 1e-300))
print(f"weights, largest relative difference over {n} series-region segments: "
      f"front {worst[0]:.2g}, back {worst[1]:.2g}")
PY
