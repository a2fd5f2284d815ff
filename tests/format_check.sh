#!/usr/bin/env bash
# Every C and C++ file of the tree is as the root's .clang-format writes it (Debian 12's
# clang-format 14, which scripts/setup.sh installs). Skipped (77) where there is no clang-format
# or no git checkout to list the files.
# usage: format_check.sh SOURCE_DIR
set -u
cd "$1" || exit 1
command -v clang-format >/dev/null || { echo "no clang-format: skipped"; exit 77; }
files=$(git ls-files '*.cpp' '*.hpp' '*.h' '*.c' 2>/dev/null) || { echo "not a git checkout: skipped"; exit 77; }
off=0; n=0
for f in $files; do
  n=$((n + 1))
  clang-format --dry-run -Werror "$f" >/dev/null 2>&1 || { echo "off .clang-format: $f (clang-format -i $f)"; off=$((off + 1)); }
done
echo "$((n - off)) passed, $off failed"
[ "$off" -eq 0 ]
