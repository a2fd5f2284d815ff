#!/usr/bin/env bash
# Playing a time series (issue 20): per series length, the wall time of `render --animate` with the
# background thread and without it (--no-prefetch), what the thread hid (making the frames: reading
# key frames and interpolating, against the time the renders waited for it), and the peak memory,
# which must not grow with the series' length (only two key frames are held).
# usage: bash bench/time_series.sh [BUILD_DIR] [N]   (swirl -n N: 3N^3 hexahedra; default 70, 1.03M
# cells: about 6 minutes and 1 GB of disk in a temporary folder on 2 cores)
set -euo pipefail
exe=${1:-build}/bin/cellproj
n=${2:-70}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
stat() { python3 -c "import json,sys; d=json.loads(sys.stdin.read().splitlines()[-1]); print(' '.join(str(round(d[k],3)) if isinstance(d[k],float) else str(d[k]) for k in sys.argv[1:]))" "$@"; }
printf '%-6s %-8s %-11s %7s %6s %10s %10s %12s %12s %9s\n' steps frames mode wall_s frame_s key_reads make_s waited_s hidden peak_MiB
for steps in 4 16; do
  "$exe" generate swirl -n "$n" --steps "$steps" -o "$tmp/s$steps/s.pvd" >/dev/null
  frames=$((2 * steps))
  for mode in prefetch no-prefetch; do
    flag=""; [ $mode = no-prefetch ] && flag=--no-prefetch
    t0=$(date +%s%N)
    line=$("$exe" render "$tmp/s$steps/s.pvd" --animate "0:$((steps - 1)):$frames" --method pt-linear --size 512x512 \
      -o "$tmp/f/%04d.png" --threads 2 --stats $flag 2>&1 >/dev/null | stat frame_seconds key_frames_read series_make_seconds series_wait_seconds peak_rss_mib)
    t1=$(date +%s%N)
    read -r frame reads make waited peak <<<"$line"
    hidden=$(python3 -c "print(f'{1 - $waited / $make:.1%}' if $make > 0 else '-')")
    printf '%-6s %-8s %-11s %7.1f %6s %10s %10s %12s %12s %9s\n' "$steps" "$frames" "$mode" \
      "$(python3 -c "print(($t1 - $t0) / 1e9)")" "$frame" "$reads" "$make" "$waited" "$hidden" "$peak"
  done
  rm -rf "$tmp/s$steps"
done
