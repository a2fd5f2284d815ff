#!/usr/bin/env bash
# Iso-surfaces with the volume (issue 19): each --iso-mode's error against `ordered` (the exact
# order along each ray) and its frame time, on four scenes: the default scene with two
# semi-transparent surfaces and the volume, three nested spheres (generate shells) without it,
# a time-varying field halfway between its two key frames (generate swirl --steps 2), and two
# intersecting meshes (bench/scenes/two_volumes.sh: a ring's volume through a ball's surfaces); then the
# "popping" of each mode: the mean frame-to-frame change over 36 frames of a full turn (the series:
# of its playback from one key frame to the other); a mode that pops changes more than ordered.
# usage: bash bench/iso_modes.sh [BUILD_DIR]    (about 6 minutes on 2 cores; numpy: Debian's python3)
set -euo pipefail
exe=${1:-build}/bin/cellproj
src=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$exe" generate shells-tets -n 32 -o "$tmp/shells.vtu" >/dev/null
"$exe" generate swirl -n 16 --steps 2 -o "$tmp/series/s.pvd" >/dev/null
bash "$src/bench/scenes/two_volumes.sh" "$tmp/two" "$exe" >/dev/null
declare -A args=(
  [default]="$src/scenes/default.json --iso 0.3:0.3,0.5,1,0.35 --iso 0.6:1,0.5,0.2,0.5"
  [shells]="$tmp/shells.vtu --view iso --iso 0.5:1,0.3,0.2,0.3 --iso 0:0.3,0.9,0.3,0.3 --iso -0.5:0.2,0.4,1,0.3 --volume off"
  [series]="$tmp/series/s.pvd --view iso --iso 0.3:0.3,0.5,1,0.35 --iso 0.6:1,0.5,0.2,0.5"
  [two]="$tmp/two/two_volumes.json"
)
declare -A still=([default]="" [shells]="" [series]="--time 0.5" [two]="")
declare -A turn=([default]="--orbit 360 --frames 36" [shells]="--orbit 360 --frames 36" [series]="--animate 0:1:36"
                 [two]="--orbit 360 --frames 36")
printf '%-8s %-8s %10s %10s %10s %14s\n' scene mode max_abs rmse s/frame turntable_mean
for scene in default shells series two; do
  for mode in ordered blend2 oit3 oit4; do
    # shellcheck disable=SC2086
    out=$("$exe" render ${args[$scene]} ${still[$scene]} --method exact --iso-mode $mode --size 256x256 --npy "$tmp/$mode.npy" \
      -o "$tmp/$mode.png" 2>/dev/null | tail -1)
    secs=$(sed -nE 's/.*, ([0-9.]+) s per frame.*/\1/p' <<<"$out")
    read -r max rmse < <("$exe" compare "$tmp/ordered.npy" "$tmp/$mode.npy" | sed -E 's/.*"max_abs": ([^,]+), "rmse": ([^}]+)}.*/\1 \2/')
    # shellcheck disable=SC2086
    "$exe" render ${args[$scene]} ${turn[$scene]} --method exact --iso-mode $mode --size 128x128 \
      --npy "$tmp/turn_$mode/%02d.npy" -o "$tmp/turn_$mode/%02d.png" >/dev/null 2>&1
    pop=$("${PYTHON:-/usr/bin/python3}" - "$tmp/turn_$mode" <<'PY'
import sys, glob, numpy as np
frames = [np.load(f)[..., :3] for f in sorted(glob.glob(sys.argv[1] + "/*.npy"))]
print(f"{np.mean([np.abs(a - b).mean() for a, b in zip(frames, frames[1:] + frames[:1])]):.5f}")
PY
)
    printf '%-8s %-8s %10s %10s %10s %14s\n' $scene $mode "$max" "$rmse" "$secs" "$pop"
  done
done
