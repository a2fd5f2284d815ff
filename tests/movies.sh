#!/usr/bin/env bash
# Movies and EXRs through the command line (issue 58): a 36-frame turntable written as MP4 and as
# GIF has 36 frames (ffprobe, which is FFmpeg's and not ours) of the picture's size; its peak memory
# does not grow with the frame count (frames are encoded as they come, none held); a frame of the
# movie decoded looks like the PNG of the same frame; an EXR read back equals the float image; a
# movie render that fails leaves no half movie; bad combinations exit 1 or 2 with a message.
# usage: movies.sh CELLPROJ
set -u
exe=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failed=0; passed=0
fail() { echo "FAIL: $*"; failed=$((failed+1)); }
ok() { passed=$((passed+1)); }
command -v ffprobe >/dev/null || { echo "ffprobe (Debian's ffmpeg) is missing: scripts/setup.sh installs it"; exit 1; }
frames_of() { ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$1"; }
size_of() { ffprobe -v error -select_streams v:0 -show_entries stream=width,height -of csv=s=x:p=0 "$1"; }
peak() { python3 -c "import json,sys; print(json.loads(sys.stdin.read().strip().splitlines()[-1])['peak_rss_mib'])"; }

"$exe" generate swirl -n 10 -o "$tmp/swirl.vtu" >/dev/null || fail "generate"
turn=(render "$tmp/swirl.vtu" --orbit 360 --size 320x240 --legend --title Swirl)

for ext in mp4 gif; do
  "$exe" "${turn[@]}" --frames 36 -o "$tmp/turn.$ext" >"$tmp/out.txt" || { fail "render turn.$ext"; continue; }
  grep -q "wrote $tmp/turn.$ext (36 frames" "$tmp/out.txt" && ok || fail "turn.$ext: $(cat "$tmp/out.txt")"
  n=$(frames_of "$tmp/turn.$ext"); [ "$n" = 36 ] && ok || fail "turn.$ext has $n frames, not 36"
  # The picture's size: 320x240, a title strip above and the legend's strip beside (MP4: even sides).
  "$exe" "${turn[@]}" --frames 36 -o "$tmp/f_%02d.png" >/dev/null || fail "render the PNG frames"
  png=$(python3 -c "import struct,sys; d=open(sys.argv[1],'rb').read(24); w,h=struct.unpack('>II',d[16:24]); print(w,h)" "$tmp/f_09.png")
  read -r w h <<<"$png"
  [ "$ext" = mp4 ] && w=$((w + w % 2)) && h=$((h + h % 2))
  s=$(size_of "$tmp/turn.$ext"); [ "$s" = "${w}x${h}" ] && ok || fail "turn.$ext is $s, the PNG ${w}x${h}"
  # Frame 10 decoded against the PNG of frame 10: mean difference within what H.264 or a
  # palette leaves (a wrong colour matrix, channel order or frame would be far off).
  ffmpeg -v error -y -i "$tmp/turn.$ext" -vf "select=eq(n\,9)" -frames:v 1 -pix_fmt rgb24 -f rawvideo "$tmp/f9.rgb" || fail "decode turn.$ext"
  ffmpeg -v error -y -i "$tmp/f_09.png" -vf "pad=$w:$h" -pix_fmt rgb24 -f rawvideo "$tmp/p9.rgb" || fail "decode f_09.png"
  python3 - "$tmp/f9.rgb" "$tmp/p9.rgb" "$ext" <<'PY' && ok || fail "turn.$ext frame 10 differs from f_09.png"
import sys
a, b = open(sys.argv[1], 'rb').read(), open(sys.argv[2], 'rb').read()
assert len(a) == len(b) and len(a) > 0, (len(a), len(b))
mean = sum(abs(x - y) for x, y in zip(a, b)) / len(a)
print(f"{sys.argv[3]}: frame 10 against its PNG: mean |difference| {mean:.2f} of 255")
sys.exit(0 if mean < 3.0 else 1)
PY
done

# Peak memory does not grow with the frame count: 60 and 180 frames of a 320x240 turntable (past
# the ~50 frames x264 looks ahead, which is its own bounded buffer). Were the frames held, 120 more
# would take 120 x 320 x 240 x 3 bytes = 26 MiB at the least.
# (Under AddressSanitizer freed memory waits in its quarantine, which grows the peak with any work:
# it is turned off for these two runs.)
for n in 60 180; do
  ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}quarantine_size_mb=0 "$exe" render "$tmp/swirl.vtu" --orbit 360 --size 320x240 --frames $n -o "$tmp/m$n.mp4" --stats 2>"$tmp/s$n.txt" >/dev/null || fail "render $n frames"
done
p60=$(peak <"$tmp/s60.txt"); p180=$(peak <"$tmp/s180.txt")
python3 -c "import sys; a,b=float(sys.argv[1]),float(sys.argv[2]); print(f'peak memory: 60 frames {a:.1f} MiB, 180 frames {b:.1f} MiB'); sys.exit(0 if b < a + 8 else 1)" "$p60" "$p180" \
  && ok || fail "peak memory grows with frames: $p60 MiB for 60, $p180 MiB for 180"
[ "$(frames_of "$tmp/m180.mp4")" = 180 ] && ok || fail "m180.mp4 does not have 180 frames"

# An EXR is the float image: against the .npy of the same render, to float precision.
"$exe" render "$tmp/swirl.vtu" --size 96x80 --background none -o "$tmp/t.exr" --npy "$tmp/t.npy" >/dev/null || fail "render t.exr"
d=$("$exe" compare "$tmp/t.exr" "$tmp/t.npy") || fail "compare t.exr t.npy"
python3 -c "import json,sys; d=json.loads(sys.argv[1]); print('exr against npy:', d); sys.exit(0 if d['max_abs'] <= 1e-6 else 1)" "$d" \
  && ok || fail "t.exr differs from t.npy: $d"
"$exe" render "$tmp/swirl.vtu" --size 64x48 --frames 3 -o "$tmp/e_%d.exr" >/dev/null && [ -f "$tmp/e_2.exr" ] && ok || fail "an EXR frame pattern"

# Refusals: exit code and message; no file left behind.
expect() {  # expect CODE REGEX ARGS...
  local code=$1 re=$2; shift 2
  "$exe" "$@" >"$tmp/o.txt" 2>&1; local rc=$?
  if [ $rc -eq "$code" ] && grep -Eq "$re" "$tmp/o.txt"; then ok; else fail "$* -> exit $rc: $(head -3 "$tmp/o.txt")"; fi
}
expect 1 "a movie has no alpha" render "$tmp/swirl.vtu" --frames 3 --size 32x32 --background none -o "$tmp/clear.mp4"
expect 1 "is a movie, not a PNG" render "$tmp/swirl.vtu" --frames 3 --size 32x32 --png-bits 16 -o "$tmp/deep.gif"
expect 2 "a movie is one file" render "$tmp/swirl.vtu" --frames 3 --size 32x32 -o "$tmp/t_%02d.mp4"
expect 2 "give a frame pattern" render "$tmp/swirl.vtu" --frames 3 --size 32x32 -o "$tmp/t.mp4" --npy "$tmp/t.npy"
expect 2 "fps" render "$tmp/swirl.vtu" --frames 3 --size 32x32 -o "$tmp/t.mp4" --fps 0
expect 1 "no such folder" render "$tmp/swirl.vtu" --frames 3 --size 32x32 -o "$tmp/missing/t.mp4"
for f in clear.mp4 deep.gif t.mp4; do [ -e "$tmp/$f" ] && fail "$f was left behind" || ok; done

echo "movies: $passed passed, $failed failed"
[ $failed -eq 0 ]
