#!/usr/bin/env bash
# The exact renderer's two cell interpolations on the default scene (and on Blunt Fin when
# ../shared/data is there): time per frame and how far apart the pictures are (docs/methods.md).
# usage: bash bench/isoparametric.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build}
exe=$build/bin/cellproj
here=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
scenes=("$here/scenes/default.json")
[ -f "$here/../shared/data/nasa_bluntfin/bluntfinxyz.bin" ] && scenes+=("$here/bench/scenes/bluntfin.json")
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .json)
  for mode in isoparametric canonical-tets; do
    "$exe" render "$scene" --method exact --interpolation "$mode" -o "$tmp/$name-$mode.png" --npy "$tmp/$name-$mode.npy" --stats \
      2>"$tmp/stats" >/dev/null
    echo "$name $mode: $(grep -o '"frame_seconds":[0-9.]*' "$tmp/stats")"
  done
  echo "$name isoparametric vs canonical-tets: $("$exe" compare "$tmp/$name-isoparametric.npy" "$tmp/$name-canonical-tets.npy")"
done
