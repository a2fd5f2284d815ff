#!/usr/bin/env bash
# Culling cells that cannot show (issue 21): cell projection of the 1M-tetrahedron box at 1024²
# (2 threads, sort included) with a transfer function clear below a scalar value, leaving out the
# cells whose whole scalar range is clear (--cull-transparent on, the default) against drawing
# them all (off), in one run: the ratio of frame times, and the pictures' difference (must be 0).
# usage: bash bench/cull_transparent.sh [BUILD_DIR]   (about 3 minutes on 2 cores)
set -euo pipefail
exe=${1:-build}/bin/cellproj
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$exe" generate box-tets -n 56 -o "$tmp/box.vtu" >/dev/null
printf '%-15s %-6s %9s %12s %12s %8s %10s\n' method clear_below culled_cells on_s off_s ratio max_abs
for clear in 0.5 0.8; do
  cat > "$tmp/scene.json" <<JSON
{ "mesh": "box.vtu", "field": "scalar",
  "transfer_function": { "color": [[0, 0.2, 0.3, 0.9], [0.6, 0.9, 0.8, 0.3], [1, 1, 0.3, 0.1]],
                         "extinction": [[$clear, 0.0], [$clear, 1.0], [1, 8.0]] },
  "camera": { "projection": "perspective", "eye": [3.5, 2.5, 4.5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 35 } }
JSON
  for m in pt-linear pt-breakpoints; do
    for c in on off; do
      "$exe" render "$tmp/scene.json" --method "$m" --size 1024x1024 --threads 2 --frames 3 --cull-transparent $c \
        --npy "$tmp/$c.npy" -o "$tmp/$c.png" --stats 2>"$tmp/$c.err" >/dev/null
    done
    read -r culled on < <(python3 -c 'import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); print(d["cells_culled_transparent"], d["frame_seconds"])' "$tmp/on.err")
    off=$(python3 -c 'import json,sys; print(json.loads(open(sys.argv[1]).read().splitlines()[-1])["frame_seconds"])' "$tmp/off.err")
    diff=$("$exe" compare "$tmp/on.npy" "$tmp/off.npy" | sed -E 's/.*"max_abs": ([^,]+),.*/\1/')
    printf '%-15s %-6s %9s %12.3f %12.3f %8.2f %10s\n' "$m" "$clear" "$culled" "$on" "$off" \
      "$(python3 -c "print($off / $on)")" "$diff"
  done
done
