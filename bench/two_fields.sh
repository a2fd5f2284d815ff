#!/usr/bin/env bash
# Colour by one field, extinction by another (--opacity-field): per mesh, the time per frame of
# pt-breakpoints with one field and with two (each cell then ray cast over its canonical
# tetrahedra instead of projected), their ratio measured in this run, the exact renderer's time
# with two fields, and pt-breakpoints' largest difference from it. On the generated meshes the
# opacity field is the colour field itself (the one-field picture, drawn the two-field way); on the
# shared Exodus disk it is the velocity's magnitude, the colour the temperature.
# usage: bash bench/two_fields.sh [BUILD_DIR] [SIZE]     (about a minute on 2 cores)
set -euo pipefail
exe=${1:-build}/bin/cellproj
size=${2:-512}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$exe" generate box-tets -n 30 -o "$tmp/box-tets.vtu" >/dev/null
"$exe" generate mixed -n 16 -o "$tmp/mixed.vtu" >/dev/null
disk=$(dirname "$0")/../../shared/data/exodus_disk_out_ref/disk_out_ref.ex2
seconds() { sed -nE 's/.*"frame_seconds":([0-9.e-]+).*/\1/p' "$1"; }
frame() {  # frame OUT.npy STATS ARGS...: one frame's array and its --stats
  local out=$1 stats=$2; shift 2
  "$exe" render "$@" --size "${size}x${size}" --npy "$out" -o "$tmp/x.png" --stats 2>"$stats" >/dev/null
}
printf '%-10s %8s %12s %12s %8s %12s %12s\n' mesh cells one_field_s two_fields_s ratio exact_2f_s max_abs
for mesh in box-tets mixed disk; do
  if [ $mesh = disk ]; then
    [ -f "$disk" ] || continue
    file=$disk; color=(--field Temp); opacity=(--opacity-field V)
  else
    file=$tmp/$mesh.vtu; color=(); opacity=(--opacity-field scalar)
  fi
  frame "$tmp/one.npy" "$tmp/one.json" "$file" "${color[@]}"
  frame "$tmp/two.npy" "$tmp/two.json" "$file" "${color[@]}" "${opacity[@]}"
  frame "$tmp/exact.npy" "$tmp/exact.json" "$file" "${color[@]}" "${opacity[@]}" --method exact
  one=$(seconds "$tmp/one.json") two=$(seconds "$tmp/two.json") ex=$(seconds "$tmp/exact.json")
  cells=$(sed -nE 's/.*"cells":([0-9]+).*/\1/p' "$tmp/one.json")
  max=$("$exe" compare "$tmp/two.npy" "$tmp/exact.npy" | sed -E 's/.*"max_abs": ([^,]+),.*/\1/')
  printf '%-10s %8s %12.3f %12.3f %8.2f %12.3f %12s\n' $mesh "$cells" "$one" "$two" "$(echo "$two / $one" | bc -l)" "$ex" "$max"
done
