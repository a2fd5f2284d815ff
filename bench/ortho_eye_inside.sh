#!/usr/bin/env bash
# An orthographic eye inside the mesh: every method must draw only what lies in front of the eye's
# plane, as the exact renderer does. Prints, per mesh and method, the error against exact with the
# eye inside and with the eye moved out along the same view direction (the method's own error),
# and the time per frame of each pt-breakpoints render.
# usage: bash bench/ortho_eye_inside.sh [BUILD_DIR]     (about 20 s on 2 cores)
set -euo pipefail
exe=${1:-build}/bin/cellproj
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$exe" generate box-tets -n 12 -o "$tmp/tets.vtu" >/dev/null
"$exe" generate mixed -n 6 -o "$tmp/mixed.vtu" >/dev/null
tf='"transfer_function": {"color": [[0, 1, 0.5, 0.2], [1, 0.2, 0.5, 1]], "extinction": [[0, 2], [1, 4]]}'
printf '%-6s %-8s %-15s %10s %10s %10s\n' mesh eye method max_abs rmse s/frame
for mesh in tets mixed; do
  for eye in inside outside; do
    e='[0.2, 0.1, 0.3]'; [ $eye = outside ] && e='[1.6, 0.9, 3.1]'  # the same direction to the target
    echo "{\"mesh\": \"$mesh.vtu\", $tf, \"camera\": {\"projection\": \"orthographic\", \"eye\": $e, \"target\": [-0.5, -0.3, -1], \"up\": [0, 1, 0]}}" >"$tmp/$mesh-$eye.json"
    "$exe" render "$tmp/$mesh-$eye.json" --size 256x256 --method exact --npy "$tmp/exact.npy" -o "$tmp/x.png" >/dev/null 2>&1
    for m in pt-breakpoints slicing; do
      out=$("$exe" render "$tmp/$mesh-$eye.json" --size 256x256 --method $m --npy "$tmp/$m.npy" -o "$tmp/x.png" 2>/dev/null | tail -1)
      secs=$(sed -nE 's/.*, ([0-9.]+) s per frame.*/\1/p' <<<"$out")
      read -r max rmse < <("$exe" compare "$tmp/exact.npy" "$tmp/$m.npy" | sed -E 's/.*"max_abs": ([^,]+), "rmse": ([^}]+)}.*/\1 \2/')
      printf '%-6s %-8s %-15s %10s %10s %10s\n' $mesh $eye $m "$max" "$rmse" "$secs"
    done
  done
done
