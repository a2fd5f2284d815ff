#!/usr/bin/env bash
# Early ray termination (issue 21): cell projection of the 1M-tetrahedron box at 1024² (2 threads,
# sort included) with bench/scenes/box_1m.json's transfer function, its extinction times K, tiles
# composited front to back (--early-termination on) against back to front (off, the default), in
# one run (on, off, off, on: drift favours neither): the cells and fragments left out, the ratio of
# frame times (off / on: above 1 is faster) and the pictures' difference (within 2e-6).
# usage: bash bench/early_termination.sh [BUILD_DIR]   (about 6 minutes on 2 cores)
set -euo pipefail
exe=${1:-build}/bin/cellproj
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$exe" generate box-tets -n 55 -o "$tmp/box.vtu" >/dev/null
frame() {  # K METHOD on|off -> the run's median frame seconds; its stats in $tmp/$3.err
  "$exe" render "$tmp/k$1.json" --method "$2" --size 1024x1024 --threads 2 --frames 3 --early-termination "$3" \
    --npy "$tmp/$3.npy" -o "$tmp/$3.png" --stats 2>"$tmp/$3.err" >/dev/null
  python3 -c 'import json,sys; print(json.loads(open(sys.argv[1]).read().splitlines()[-1])["frame_seconds"])' "$tmp/$3.err"
}
printf '%-4s %-15s %12s %12s %12s %8s %8s %8s %10s %10s\n' K method hidden_cells fragments_on fragments_off on_s off_s \
  off/on max_abs rmse
for k in 1 5 20; do
  cat >"$tmp/k$k.json" <<JSON
{ "mesh": "box.vtu", "field": "scalar",
  "transfer_function": { "color": [[0, 0.2, 0.3, 0.9], [0.6, 0.9, 0.8, 0.3], [1, 1, 0.3, 0.1]],
                         "extinction": [[0, $(python3 -c "print(0.2*$k)")], [0.6, $((1 * k))], [0.8, $((4 * k))], [1, $((8 * k))]] },
  "camera": { "projection": "perspective", "eye": [3.5, 2.5, 4.5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 35 } }
JSON
  for m in pt-linear pt-table pt-breakpoints; do
    on1=$(frame $k $m on); off1=$(frame $k $m off); off2=$(frame $k $m off); on2=$(frame $k $m on)
    read -r hidden f_on < <(python3 -c 'import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); print(d["hidden_cells"], d["fragments"])' "$tmp/on.err")
    f_off=$(python3 -c 'import json,sys; print(json.loads(open(sys.argv[1]).read().splitlines()[-1])["fragments"])' "$tmp/off.err")
    read -r max rmse < <("$exe" compare "$tmp/on.npy" "$tmp/off.npy" | python3 -c 'import json,sys; d=json.load(sys.stdin); print(d["max_abs"], d["rmse"])')
    python3 - "$k" "$m" "$hidden" "$f_on" "$f_off" "$on1" "$on2" "$off1" "$off2" "$max" "$rmse" <<'PY'
import sys
k, m, hidden, f_on, f_off = sys.argv[1:6]
on = (float(sys.argv[6]) + float(sys.argv[7])) / 2; off = (float(sys.argv[8]) + float(sys.argv[9])) / 2
print(f"{k:4s} {m:15s} {hidden:>12s} {f_on:>12s} {f_off:>12s} {on:8.3f} {off:8.3f} {off / on:8.2f} {float(sys.argv[10]):10.2e} {float(sys.argv[11]):10.2e}")
PY
  done
done
