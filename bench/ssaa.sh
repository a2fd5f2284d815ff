#!/usr/bin/env bash
# Anti-aliasing (docs/accuracy.md, "Anti-aliasing"): on a graded mesh whose cells near one face
# are far below a pixel, each method at --ssaa 1, 2, 4 with the box and the tent filter against
# the exact image at 8 x 8 samples per pixel filtered the same way.
# usage: bench/ssaa.sh [BUILD_DIR]   (about a minute)
set -euo pipefail
exe=${1:-build}/bin/cellproj
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$exe" generate graded-tets -n 8 -o "$tmp/g.vtu" >/dev/null
"$exe" render "$tmp/g.vtu" --method exact --size 1024x1024 --npy "$tmp/ref.npy" -o "$tmp/ref.png" >/dev/null
echo "| method | filter | RMSE, ssaa 1 | ssaa 2 | ssaa 4 | max, ssaa 1 | ssaa 4 |"
echo "| --- | --- | ---: | ---: | ---: | ---: | ---: |"
for m in pt-linear pt-breakpoints exact "slicing --slices 256"; do
  for f in box tent; do
    name=${m%% *}; [ "$m" = "$name" ] || name+=" (256 planes)"
    row="| $name | $f |"; max=""
    for n in 1 2 4; do
      # shellcheck disable=SC2086  # the method's options
      "$exe" render "$tmp/g.vtu" --method $m --ssaa $n --ssaa-filter $f --size 128x128 --npy "$tmp/m.npy" \
        -o "$tmp/m.png" >/dev/null 2>&1
      d=$("$exe" compare "$tmp/m.npy" "$tmp/ref.npy" --downsample 8 --filter $f)
      row+=" $(echo "$d" | sed 's/.*"rmse": \([^}]*\)}.*/\1/') |"
      if [ $n != 2 ]; then max+=" $(echo "$d" | sed 's/.*"max_abs": \([^,]*\),.*/\1/') |"; fi
    done
    echo "$row$max"
  done
done
