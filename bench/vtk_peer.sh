#!/usr/bin/env bash
# cellproj's projection methods against VTK 9's unstructured-grid volume mappers on the same
# scenes, in one run: vtkProjectedTetrahedraMapper (OpenGL: Mesa's llvmpipe under Xvfb, all
# cores), and on the small meshes vtkUnstructuredGridVolumeRayCastMapper and
# vtkUnstructuredGridVolumeZSweepMapper (CPU). Time per frame, ratio to VTK's projected
# tetrahedra, and the error of each picture (RGB on black) against cellproj's exact renderer.
# usage: bench/vtk_peer.sh [BUILD_DIR] [DIR]
#   DIR must hold bench/projection.py's output (its exact images and the 1M-tetrahedron scene):
#   python3 bench/projection.py --out DIR first.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}; dir=${2:-bench-out}
exe=$build/bin/cellproj
need=()
for p in xvfb xauth python3-numpy python3-vtk9; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || need+=("$p")
done
if [ ${#need[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${need[@]}" >&2
fi
py=/usr/bin/python3  # Debian's python, where python3-vtk9 and python3-numpy live

err() {  # err IMAGE.npy EXACT.npy -> "rmse max" of RGB on black
  $py -c 'import sys, numpy as np
a = np.clip(np.load(sys.argv[1])[..., :3], 0, 1); e = np.clip(np.load(sys.argv[2])[..., :3], 0, 1)
d = np.abs(a - e); print(f"{np.sqrt((d * d).mean()):.2e} | {d.max():.2e}")' "$1" "$2"
}
median() { $py -c 'import json, sys; print(f"{json.loads(sys.stdin.read().strip().splitlines()[-1])[sys.argv[1]]:.3f}")' "$1"; }

echo "| scene | size | renderer | median s per frame | VTK / this | RMSE vs exact | max vs exact |"
echo "|---|---|---|---|---|---|---|"
for spec in "box1m:$dir/box1m.json:1024" "post_tets:$root/bench/scenes/post_tets.json:512" \
            "post_tets:$root/bench/scenes/post_tets.json:1024" "static_mixer:$root/bench/scenes/static_mixer.json:1024"; do
  IFS=: read -r tag scene size <<< "$spec"
  [ -f "$scene" ] && [ -f "$dir/${tag}_${size}_exact.npy" ] || { echo "skipping $tag $size (run bench/projection.py --out $dir)" >&2; continue; }
  peer() {  # peer MAPPER -> median seconds, picture in DIR
    xvfb-run -a -s "-screen 0 1280x1280x24" $py "$root/bench/vtk_peer.py" "$scene" --size "$size" --frames 4 \
      --mapper "$1" --out "$dir/${tag}_${size}_vtk-$1" | median median_seconds
  }
  vtk=$(peer pt)
  echo "| $tag | ${size}² | vtkProjectedTetrahedraMapper | $vtk | 1 | $(err "$dir/${tag}_${size}_vtk-pt.npy" "$dir/${tag}_${size}_exact.npy") |"
  if [ "$tag" != box1m ]; then  # the CPU mappers take minutes per frame on 1M cells
    for m in raycast zsweep; do
      t=$(peer $m)
      echo "| $tag | ${size}² | vtk $m | $t | $($py -c "print(f'{$vtk / $t:.2f}')") | $(err "$dir/${tag}_${size}_vtk-$m.npy" "$dir/${tag}_${size}_exact.npy") |"
    done
  fi
  for m in pt-linear pt-table pt-analytic; do
    t=$("$exe" render "$scene" --method "$m" --size "${size}x${size}" --frames 3 --threads 2 --stats \
          -o "$dir/${tag}_${size}_peer_$m.png" --npy "$dir/${tag}_${size}_peer_$m.npy" 2>&1 >/dev/null | median frame_seconds)
    ratio=$($py -c "print(f'{$vtk / $t:.2f}')")
    echo "| $tag | ${size}² | cellproj $m | $t | $ratio | $(err "$dir/${tag}_${size}_peer_$m.npy" "$dir/${tag}_${size}_exact.npy") |"
  done
done
