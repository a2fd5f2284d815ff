#!/usr/bin/env bash
# Writes DIR/two_volumes.json, a scene of two intersecting meshes (docs/methods.md, "Several
# volumes"): a ring of hexahedra (generate swirl, its temperature drawn as volume) through a ball of
# tetrahedra (generate shells-tets, its iso-surface 0, three nested spheres, no volume), with both meshes.
# Also DIR/ring_only.json and DIR/ball_only.json, each volume alone with the same camera.
# usage: bash bench/scenes/two_volumes.sh DIR [CELLPROJ]
set -euo pipefail
dir=$1; exe=${2:-build/bin/cellproj}
mkdir -p "$dir"
"$exe" generate swirl -n 16 -o "$dir/ring.vtu" >/dev/null
"$exe" generate shells-tets -n 24 -o "$dir/ball.vtu" >/dev/null
cat > "$dir/two_volumes.json" <<'JSON'
{ "volumes": [
    { "mesh": "ring.vtu",
      "transfer_function": { "color": [[0, 0.1, 0.3, 1.0], [1.15, 0.6, 0.95, 1.0]],
                             "extinction": [[0, 0.3], [1.15, 5.0]] } },
    { "mesh": "ball.vtu",
      "transfer_function": { "color": [[-1, 1, 0.5, 0.1], [1, 1, 0.9, 0.3]], "extinction": [[-1, 0], [1, 0]] },
      "volume": false,
      "iso": [ { "value": 0, "color": [1, 0.45, 0.2], "opacity": 0.3 } ] } ],
  "camera": { "projection": "perspective", "eye": [1.6, -2.3, 3.3], "target": [0, 0, 0], "up": [0, 0, 1], "fov_y": 38 },
  "image": { "width": 512, "height": 512, "background": [0.05, 0.05, 0.07] } }
JSON
# Each volume alone, the same camera: what merging the two costs against drawing each (docs/methods.md).
python3 - "$dir" <<'PY'
import json, sys
d = sys.argv[1]
s = json.load(open(f"{d}/two_volumes.json"))
for k, name in [(0, "ring_only"), (1, "ball_only")]:
    json.dump(dict(s, volumes=[s["volumes"][k]]), open(f"{d}/{name}.json", "w"))
PY
echo "$dir/two_volumes.json"
