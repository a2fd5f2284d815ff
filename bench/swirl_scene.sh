#!/usr/bin/env bash
# The 1M-cell curvilinear `swirl` grid (210 x 70 x 70 hexahedra with warped faces at N=70) and its
# scene (close perspective view, 512^2 by default) into DIR: DIR/swirl.vtu and DIR/scene.json, the
# scene of bench/curvilinear_1m.sh and of side-by-side runs such as
#   bash bench/swirl_scene.sh /tmp/swirl && bash bench/ab_frames.sh A B /tmp/swirl/scene.json pt-breakpoints 1024
# usage: bench/swirl_scene.sh DIR [N] [CELLPROJ]
set -euo pipefail
dir=$1; n=${2:-70}; exe=${3:-$(dirname "$0")/../build/bin/cellproj}
mkdir -p "$dir"
"$exe" generate swirl -n "$n" -o "$dir/swirl.vtu"
cat > "$dir/scene.json" <<JSON
{ "mesh": "swirl.vtu", "field": "temperature",
  "transfer_function": { "color": [[0, 0.1, 0.2, 0.8], [0.5, 0.2, 0.8, 0.7], [0.8, 1, 0.8, 0.2], [1.2, 1, 0.2, 0.1]],
                         "extinction": [[0, 0.1], [0.5, 1.5], [0.8, 4.0], [1.2, 8.0]] },
  "camera": { "projection": "perspective", "eye": [2.2, -2.8, 2.0], "target": [0, 0, 0], "up": [0, 0, 1], "fov_y": 38 },
  "image": { "width": 512, "height": 512 } }
JSON
