#!/usr/bin/env bash
# Runs the README's snippets marked <!-- readme-test: sh|python --> as a new user would, from a
# folder holding the clone's scenes/ and the build tree (as build/).
# usage: readme_snippets.sh SOURCE_DIR BUILD_DIR [PYTHON]
set -eu
src=$1; build=$2; python=${3:-}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
ln -s "$src/scenes" "$work/scenes"; ln -s "$build" "$work/build"; mkdir -p "$work/out"
# Each marked block into its own file: snippet-N.sh or snippet-N.py.
awk -v dir="$work" '
  /<!-- readme-test: (sh|python) -->/ { kind = ($0 ~ /python/) ? "py" : "sh"; want = 1; next }
  want && /^```/ { if (inside) { inside = 0; want = 0; close(file) } else { inside = 1; n++; file = dir "/snippet-" n "." kind } ; next }
  inside { print > file }
' "$src/README.md"
passed=0; failed=0
for f in "$work"/snippet-*; do
  case $f in
    *.py) [ -n "$python" ] || { echo "skipped $(basename "$f"): no Python module"; continue; }
          run=(env PYTHONPATH="$work/build/python" "$python" "$f") ;;
    *) run=(bash -eu "$f") ;;
  esac
  if (cd "$work" && "${run[@]}"); then passed=$((passed + 1)); else echo "FAIL: README snippet:"; cat "$f"; failed=$((failed + 1)); fi
done
[ -s "$work/out/quick.png" ] || { echo "FAIL: the one-line render wrote no out/quick.png"; failed=$((failed + 1)); }
[ -z "$python" ] || [ -s "$work/out/python.png" ] || { echo "FAIL: the Python quick start wrote no PNG"; failed=$((failed + 1)); }
[ "$passed" -ge 1 ] || { echo "FAIL: no README snippet found"; failed=$((failed + 1)); }
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
