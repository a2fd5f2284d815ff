#!/usr/bin/env bash
# The command line on bad input: a clear message on stderr and the documented exit code.
# usage: cli_errors.sh CELLPROJ SOURCE_DIR [ON|OFF: the OpenGL back ends built]
set -u
exe=$1; src=$2; gl=${3:-ON}  # gl: whether the OpenGL back ends were built
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failed=0; passed=0

expect() {  # expect CODE REGEX -- ARGS...
  local code=$1 regex=$2; shift 3
  "$exe" "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?
  if [ "$got" -ne "$code" ] || ! grep -Eq -- "$regex" "$tmp/err" "$tmp/out"; then
    echo "FAIL: cellproj $* -> exit $got (want $code), output:"; cat "$tmp/err" "$tmp/out"; failed=$((failed+1))
  else passed=$((passed+1)); fi
}

expect 2 "subcommand" -- 
for sub in render info generate sortbench compare scene partition; do expect 0 "Usage" -- $sub --help; done
expect 1 "missing.vtu: no such file" -- info "$tmp/missing.vtu"
touch "$tmp/mesh.stl"
expect 1 "unknown mesh format '.stl'" -- info "$tmp/mesh.stl"
printf '4 1\n0 0 0 1\n1 0 0 1\n0 nan 0 1\n0 0 1 1\n0 1 2 3\n' > "$tmp/nan.off"
expect 1 "nan.off: point 2 has a non-finite coordinate" -- info "$tmp/nan.off"
printf '# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 9\nCELL_TYPES 1\n10\n' > "$tmp/range.vtk"
expect 1 "range.vtk: cell 0 \\(tetra \\(10\\)\\) refers to point 9, out of range \\[0, 4\\)" -- info "$tmp/range.vtk"
"$exe" generate box -n 4 -o "$tmp/box.vtu" >/dev/null || { echo "FAIL: generate"; failed=$((failed+1)); }
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}' > "$tmp/broken.json"
expect 1 "broken.json: not valid JSON" -- render "$tmp/broken.json"
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, -1]]}}' > "$tmp/kappa.json"
expect 1 "kappa.json: transfer_function: extinction\[0\]: kappa = -1.* must be finite and >= 0" -- render "$tmp/kappa.json"
echo '{"mesh": "box.vtu", "field": "nope", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}}' > "$tmp/field.json"
expect 1 "no point field named 'nope'; the fields are: scalar" -- render "$tmp/field.json"
# The log scale: values not above 0 refused with their count, or floored; a floor alone is refused.
expect 2 "field 'scalar' on a log scale: [0-9]+ of 125 values are not above 0 \\(the smallest 0.000000, at point 0\\); give a floor below which values count as it \\(--log-floor\\)" -- render "$tmp/box.vtu" --log -o "$tmp/log.png"
expect 1 "--opacity-field \\(the extinction from another field than the colour\\) is drawn by --method exact, pt-breakpoints or pt-analytic, not by pt-linear" -- render "$tmp/box.vtu" --opacity-field scalar --method pt-linear -o "$tmp/o.png"
expect 1 "--opacity-field \\(the extinction from field 'scalar'\\) is drawn by --method exact, pt-breakpoints or pt-analytic, not by slicing" -- render "$tmp/box.vtu" --opacity-field scalar --method slicing -o "$tmp/o.png"
expect 2 "box.vtu: no point field named 'nope'" -- render "$tmp/box.vtu" --opacity-field nope -o "$tmp/o.png"
expect 0 "wrote .*o.png" -- render "$tmp/box.vtu" --opacity-field scalar --log --log-floor 0.01 --size 24x20 -o "$tmp/o.png"
expect 2 "--log-floor is the floor of a log scale: give --log too" -- render "$tmp/box.vtu" --log-floor 0.1 -o "$tmp/log.png"
expect 0 "wrote .*log.png" -- render "$tmp/box.vtu" --log --log-floor 0.01 --legend --size 48x32 -o "$tmp/log.png"
expect 2 "--time-label labels a time series' frames, and .*box.vtu is not one" -- render "$tmp/box.vtu" --time-label -o "$tmp/t.png"
expect 2 "--time-format: expected text with one %f, %e or %g" -- render "$tmp/box.vtu" --time-format "%s" -o "$tmp/t.png"
expect 0 "wrote .*title.png" -- render "$tmp/box.vtu" --title "A box" --legend --size 48x32 -o "$tmp/title.png"
expect 0 "wrote .*outline_1.png" -- render "$tmp/box.vtu" --outline --axes --frames 2 --orbit 90 --size 48x32 -o "$tmp/outline_%d.png"
expect 2 "--iso does not go with --log yet" -- render "$tmp/box.vtu" --log --log-floor 0.01 --method exact --iso 0.5 -o "$tmp/t.png"
echo '{"mesh": "box.vtu", "log": true, "transfer_function": {"color": [[0.1, 1, 1, 1]], "extinction": [[0.1, 1]]}}' > "$tmp/log.json"
expect 1 "box.vtu: field 'scalar' on a log scale: 8 of 125 values are not above 0" -- render "$tmp/log.json" -o "$tmp/log.png"
expect 0 "wrote .*log.png" -- render "$tmp/log.json" --log-floor 0.01 -o "$tmp/log.png" --size 16x16
expect 2 "field 'scalar:x': scalar is a scalar \\(one component\\)" -- render "$tmp/box.vtu" --field scalar:x -o "$tmp/x.png"
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}, "camera": {"up": [0, 0, 1]}}' > "$tmp/cam.json"
expect 1 "cam.json: camera: up is parallel to the view direction" -- render "$tmp/cam.json"
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}}' > "$tmp/ok.json"
expect 2 "size: expected WxH" -- render "$tmp/ok.json" --size 0x5
expect 2 "unknown method 'pt-magic'" -- render "$tmp/ok.json" --method pt-magic
expect 2 "threads" -- render "$tmp/ok.json" --threads 0
expect 0 "wrote .*ok.png" -- render "$tmp/ok.json" --size 32x24 -o "$tmp/ok.png" --npy "$tmp/ok.npy" --stats --frames 3
grep -q '"frame_seconds"' "$tmp/err" && grep -q '"load_seconds"' "$tmp/err" && grep -q '"ns_per_fragment":[0-9]' "$tmp/err" ||
  { echo "FAIL: --stats JSON"; failed=$((failed+1)); }
expect 0 "wrote .*clear.png" -- render "$tmp/ok.json" --size 32x24 -o "$tmp/clear.png" --background none --png-bits 16 --legend
expect 2 "--png-bits: 12 not in \\{8,16\\}" -- render "$tmp/ok.json" --png-bits 12
expect 2 "--background: expected R,G,B" -- render "$tmp/ok.json" --background clear
for m in pt-linear pt-table pt-analytic pt-breakpoints exact; do
  expect 0 "wrote .*$m.png .*$m" -- render "$tmp/ok.json" --size 40x30 --method $m -o "$tmp/$m.png" --npy "$tmp/$m.npy" --stats
  grep -q "\"method\":\"$m\"" "$tmp/err" || { echo "FAIL: --stats names $m"; failed=$((failed+1)); }
done
"$exe" render "$tmp/ok.json" --size 40x30 --method pt-table -o "$tmp/t.png" --stats 2>"$tmp/err" >/dev/null
for key in tets cells_split class1_tets class2_tets fragments breakpoint_cells gap_relations gaps_from gap_pair_tests phase_seconds sort; do
  grep -q "\"$key\":" "$tmp/err" || { echo "FAIL: render --stats lacks $key"; failed=$((failed+1)); }
done
# pt-breakpoints is exact for the canonical tetrahedra: the same picture as exact --interpolation canonical-tets.
"$exe" render "$tmp/ok.json" --size 40x30 --method exact --interpolation canonical-tets --npy "$tmp/ct.npy" -o "$tmp/ct.png" >/dev/null
expect 0 '"max_abs": [0-9.e-]+' -- compare "$tmp/ct.npy" "$tmp/pt-breakpoints.npy"
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if d['max_abs'] < 1e-5 else 1)" <("$exe" compare "$tmp/ct.npy" "$tmp/pt-breakpoints.npy") \
  || { echo "FAIL: pt-breakpoints differs from exact canonical-tets"; failed=$((failed+1)); }
# compare: a .npy that is not float32 names its file once; --downsample that does not divide B names B.
printf '\x93NUMPY\x01\x00\x76\x00{"descr": "<f8", "fortran_order": False, "shape": (30, 40), }' >"$tmp/f8.npy"
expect 1 "^cellproj: error: [^ ]*f8.npy: expected little-endian float32 in C order" -- compare "$tmp/ct.npy" "$tmp/f8.npy"
expect 1 "ct.npy: downsample: 7 does not divide" -- compare "$tmp/ct.npy" "$tmp/ct.npy" --downsample 7
expect 2 "unknown sort 'zsort'" -- render "$tmp/ok.json" --sort zsort
expect 1 "ok.json: reading .*box.vtu \(64 cells\) and rendering 16384x16384 needs about 9.6 GiB, more than the 2.0 GiB allowed by --max-memory" -- render "$tmp/ok.json" --size 16384x16384 --max-memory 2
# A mesh too large for memory is refused from its header, before anything is read.
printf '<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0">\n<UnstructuredGrid>\n<Piece NumberOfPoints="900000000" NumberOfCells="4000000000">\n' > "$tmp/huge.vtu"
sed 's/box.vtu/huge.vtu/' "$tmp/ok.json" > "$tmp/huge.json"
expect 1 "huge.json: reading .*huge.vtu \(4000000000 cells\) and rendering 512x512 needs about [0-9.]+ GiB, more than the 4.0 GiB allowed by --max-memory" -- render "$tmp/huge.json" --max-memory 4
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}, "camera": {"projection": "perspective", "eye": [0, 0, 0.1], "target": [0, 0, -1], "up": [0, 1, 0]}}' > "$tmp/inside.json"
[ "$gl" = ON ] && expect 0 "warning: [0-9]+ cells reach behind the eye and were not drawn" -- render "$tmp/inside.json" --size 32x32 -o "$tmp/inside.png" --method pt-table --backend opengl
"$exe" render "$tmp/inside.json" --size 32x32 -o "$tmp/inside.png" 2>"$tmp/err" >/dev/null
! grep -q "behind the eye" "$tmp/err" || { echo "FAIL: the software back end draws cells behind the eye, no warning"; failed=$((failed+1)); }
expect 2 "unknown back end 'vulkan'" -- render "$tmp/ok.json" --backend vulkan
expect 2 "unknown sort 'zsort'" -- render "$tmp/ok.json" --method exact --sort zsort
# Three sticks each lying over the next: a visibility cycle seen from above. The picture cannot be
# right everywhere, and render says so.
printf '# vtk DataFile Version 3.0\nsticks\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 12 double\n%s\nCELLS 3 15\n4 0 1 2 3\n4 4 5 6 7\n4 8 9 10 11\nCELL_TYPES 3\n10 10 10\nPOINT_DATA 12\nSCALARS s double 1\nLOOKUP_TABLE default\n0 1 2 3 4 5 6 7 8 9 10 11\n' \
  "1.6 -0.34641 0.5 -1.1 1.212436 -0.5 1.525 -0.476314 0.55 -1.175 1.082532 -0.55 -0.5 1.558846 0.5 -0.5 -1.558846 -0.5 -0.35 1.558846 0.55 -0.35 -1.558846 -0.55 -1.1 -1.212436 0.5 1.6 0.34641 -0.5 -1.175 -1.082532 0.55 1.525 0.476314 -0.55" > "$tmp/sticks.vtk"
echo '{"mesh": "sticks.vtk", "transfer_function": {"color": [[0, 1, 0, 0], [11, 0, 0, 1]], "extinction": [[0, 2]]}, "camera": {"projection": "orthographic", "eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "height": 4}}' > "$tmp/sticks.json"
expect 0 "warning: the visibility sort met 1 visibility cycle \(3 cells\) .* --method exact is exact there" -- render "$tmp/sticks.json" --size 64x64 -o "$tmp/sticks.png"
"$exe" render "$tmp/ok.json" --size 32x32 -o "$tmp/ok2.png" 2>"$tmp/err" >/dev/null
! grep -q "visibility cycles" "$tmp/err" || { echo "FAIL: a convex box has no visibility cycle, yet render warns"; failed=$((failed+1)); }
# info --overlaps: none in the box; two tetrahedra pushed into each other are named.
expect 0 "overlapping cells: none" -- info "$tmp/box.vtu" --overlaps
printf '# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 double\n0 0 0 1 0 0 0 1 0 0.2 0.2 1 0 0 0.5 1 0 0.5 0 1 0.5 0.3 0.3 -0.5\nCELLS 2 10\n4 0 1 2 3\n4 4 6 5 7\nCELL_TYPES 2\n10 10\n' > "$tmp/overlap.vtk"
expect 0 "WARNING: cells overlap in 1 pair \(first: cells 0 and 1\)" -- info "$tmp/overlap.vtk" --overlaps
expect 2 "--backend does not apply to --method exact, which reads --method, .*--interpolation" -- render "$tmp/ok.json" --method exact --backend opengl
expect 2 "--interpolation does not apply to --method pt-breakpoints, which reads .*--tetrahedralize" -- render "$tmp/ok.json" --interpolation canonical-tets
expect 2 "--tetrahedralize: unknown tetrahedralize mode 'some' \(known: problem, all, none\)" -- render "$tmp/ok.json" --tetrahedralize some
expect 2 "--tetrahedralize does not apply to --method exact" -- render "$tmp/ok.json" --method exact --tetrahedralize all
if [ "$gl" = ON ]; then
  expect 2 "OpenGL back ends draw pt-linear and pt-table only, not pt-breakpoints" -- render "$tmp/ok.json" --backend opengl
  expect 0 "wrote .*gl.png" -- render "$tmp/ok.json" --size 40x30 --method pt-table --backend opengl-8bit-dither -o "$tmp/gl.png" --stats
  grep -q '"gl_renderer":' "$tmp/err" || { echo "FAIL: --stats lacks gl_renderer"; failed=$((failed+1)); }
else  # a build without OSMesa says so, before it reads the mesh
  expect 3 "OpenGL back ends were not built" -- render "$tmp/ok.json" --method pt-table --backend opengl
fi
expect 2 "table-size" -- render "$tmp/ok.json" --method pt-table --table-size 1
expect 2 "--ssaa: expected an integer in \[1, 16\], got 0" -- render "$tmp/ok.json" --ssaa 0
expect 1 "rendering 8192x8192 needs about .* GiB" -- render "$tmp/ok.json" --ssaa 16 --size 8192x8192  # the supersampled frame counted
expect 2 "--compositing: expected tiles or stream, got 'fast'" -- render "$tmp/ok.json" --compositing fast
expect 2 "--tile-rows: expected an integer in \[0, 65536\]" -- render "$tmp/ok.json" --tile-rows -3
expect 2 "--early-termination: expected on or off, got 'maybe'" -- render "$tmp/ok.json" --early-termination maybe
expect 2 "--early-termination on composites image tiles front to back: it needs the software back end, --compositing tiles" -- render "$tmp/ok.json" --early-termination on --compositing stream
expect 2 "--early-termination does not apply to --method exact" -- render "$tmp/ok.json" --early-termination on --method exact
expect 0 '"hidden_cells":[0-9]+,"hidden_fragments":[0-9]+' -- render "$tmp/ok.json" --early-termination on --size 32x24 -o "$tmp/et.png" --stats
expect 2 "--whole-cells: expected auto, layers or polygons, got 'quads'" -- render "$tmp/ok.json" --whole-cells quads
expect 2 "--whole-cells layers needs --backend software" -- render "$tmp/ok.json" --whole-cells layers --backend opengl --method pt-linear
expect 2 "--whole-cells does not apply to --method exact" -- render "$tmp/ok.json" --whole-cells polygons --method exact
expect 2 "--whole-cells does not apply to --method pt-breakpoints" -- render "$tmp/ok.json" --whole-cells polygons
expect 2 "--compositing does not apply to --method exact" -- render "$tmp/ok.json" --method exact --compositing stream
expect 0 '"max_abs": 0, "rmse": 0' -- compare "$tmp/ok.npy" "$tmp/ok.npy"
expect 1 "no such file|cannot open" -- compare "$tmp/ok.npy" "$tmp/none.npy"
expect 2 "unknown sort 'zsort' \(known: auto, centroid" -- sortbench "$tmp/box.vtu" --sorts mpvo,zsort
expect 2 "projection" -- sortbench "$tmp/box.vtu" --projection sideways
expect 1 "missing.vtu: no such file" -- sortbench "$tmp/missing.vtu"
expect 0 '"sort":"mpvo"' -- sortbench "$tmp/box.vtu" --views 2 --size 32x32 --sorts centroid,mpvo --check --json --csv "$tmp/sorts.csv"
for key in mesh sort projection views median_seconds min_seconds max_seconds cells cells_per_second face_relations \
           gap_relations gaps gap_pair_tests abuffer_views cycles abuffer_runs abuffer_fragments abuffer_crossings violations violating_pixels; do
  grep -q "\"$key\":" "$tmp/out" || { echo "FAIL: sortbench --json lacks $key"; failed=$((failed+1)); }
done
grep -q '"sort":"mpvo".*"violations":0' "$tmp/out" || { echo "FAIL: mpvo on a box must have no violations"; failed=$((failed+1)); }
[ "$(wc -l < "$tmp/sorts.csv")" -eq 3 ] || { echo "FAIL: sortbench --csv rows"; failed=$((failed+1)); }
[ "$(stat -c %s "$tmp/ok.npy")" -eq $((128 + 32 * 24 * 16)) ] || { echo "FAIL: npy size"; failed=$((failed+1)); }

# A twisted mixed mesh: its problem cells are split per view and mpvo-abuffer's order has no violation.
"$exe" generate mixed -n 6 -o "$tmp/mixed.vtu" >/dev/null || { echo "FAIL: generate mixed"; failed=$((failed+1)); }
expect 0 '"problem_cells":[0-9]+.*"violations":0,' -- sortbench "$tmp/mixed.vtu" --views 3 --size 48x48 --sorts mpvo-abuffer --projection persp --check --json
expect 2 "unknown tetrahedralize mode 'half'" -- sortbench "$tmp/mixed.vtu" --tetrahedralize half
# The A-buffer's sweep and its reference (every pixel ordered) find the same gap relations.
# The overlaps' relations hold every one the A-buffer finds (auto: no view of this mesh needs the A-buffer).
"$exe" sortbench "$tmp/mixed.vtu" --views 3 --size 96x96 --sorts mpvo-abuffer --gaps abuffer --json > "$tmp/sweep.json" &&
  "$exe" sortbench "$tmp/mixed.vtu" --views 3 --size 96x96 --sorts mpvo-abuffer --abuffer-every-pixel --json > "$tmp/every.json" &&
  "$exe" sortbench "$tmp/mixed.vtu" --views 3 --size 96x96 --sorts mpvo-abuffer --json > "$tmp/auto.json" &&
  python3 - "$tmp/sweep.json" "$tmp/every.json" "$tmp/auto.json" <<'PY' || { echo "FAIL: --abuffer-every-pixel, --gaps"; failed=$((failed+1)); }
import json, sys
sweep, every, auto = (json.loads(open(f).readline()) for f in sys.argv[1:4])
assert not sweep["abuffer_every_pixel"] and every["abuffer_every_pixel"]
assert sweep["gap_relations"] > 0 and sweep["gap_relations"] == every["gap_relations"], (sweep["gap_relations"], every["gap_relations"])
assert 0 < sweep["abuffer_runs"] < sweep["abuffer_fragments"] <= every["abuffer_fragments"]
assert sweep["gaps"] == "abuffer" and sweep["abuffer_views"] == 3 and sweep["gap_pair_tests"] == 0
assert auto["gaps"] == "auto" and auto["abuffer_views"] == 0 and auto["gap_pair_tests"] > 0 and auto["abuffer_runs"] == 0
assert auto["gap_relations"] >= sweep["gap_relations"], (auto["gap_relations"], sweep["gap_relations"])
PY
expect 2 "unknown gap method 'pixels' \(known: auto, overlaps, abuffer\)" -- sortbench "$tmp/mixed.vtu" --gaps pixels
expect 2 "unknown gap method 'pixels'" -- render "$tmp/ok.json" --gaps pixels
# Slicing: its options, bad plane counts, progressive levels written as they complete.
expect 2 "--slices must be at least 1, not 0" -- render "$tmp/ok.json" --method slicing --slices 0
expect 2 "--slices must be at least 1, not -2" -- render "$tmp/ok.json" --method slicing --slices -2
expect 2 "slices" -- render "$tmp/ok.json" --method slicing --slices 1.5
expect 2 "--slices 600 is more than a 32x24 image can use: at most 512" -- render "$tmp/ok.json" --method slicing --slices 600 --size 32x24
expect 2 "--slice-axis: unknown slice axis 'w' \(known: auto, view, x, y, z\)" -- render "$tmp/ok.json" --method slicing --slice-axis w
expect 2 "--slice-integral: unknown slice integral 'midpoint'" -- render "$tmp/ok.json" --method slicing --slice-integral midpoint
expect 2 "--slices does not apply to --method pt-table" -- render "$tmp/ok.json" --method pt-table --slices 8
expect 2 "--sort does not apply to --method slicing" -- render "$tmp/ok.json" --method slicing --sort mpvo
expect 2 "--progressive: expected an integer, got 'x'" -- render "$tmp/ok.json" --method slicing --progressive 8,x
expect 1 "the levels must increase \(32 then 8\)" -- render "$tmp/ok.json" --method slicing --progressive 32,8 --size 32x24
expect 2 "--progressive does not apply to --method exact" -- render "$tmp/ok.json" --method exact --progressive 8,32
expect 0 "wrote .*prog-32.png" -- render "$tmp/ok.json" --method slicing --progressive 8,32 --size 32x24 -o "$tmp/prog.png" --stats
[ -s "$tmp/prog-8.png" ] && [ -s "$tmp/prog-32.png" ] && grep -q '"planes_reused":8' "$tmp/err" || { echo "FAIL: --progressive files or reuse"; failed=$((failed+1)); }
expect 0 '"slice_axis":"view".*"slices":16' -- render "$tmp/ok.json" --method slicing --slices 16 --slice-axis view --slice-integral sampled --size 32x24 -o "$tmp/sl.png" --stats
# Splatting small cells.
expect 2 "--small-cells: unknown small-cells mode 'blur' \(known: splat, draw, skip\)" -- render "$tmp/ok.json" --small-cells blur
expect 2 "--splat-threshold must be a finite number >= 0, not -1" -- render "$tmp/ok.json" --splat-threshold -1 --size 32x24
expect 2 "pre-filter must be 0.3 to 4 pixels, not 0.1" -- render "$tmp/ok.json" --splat-prefilter 0.1 --size 32x24
expect 2 "--small-cells does not apply to --method exact" -- render "$tmp/ok.json" --method exact --small-cells splat
expect 0 '"small_cells":.*"small_cells_mode":"draw"' -- render "$tmp/ok.json" --method pt-linear --size 8x6 -o "$tmp/sp.png" --stats
expect 0 '"small_cells":[1-9].*"small_cells_mode":"splat".*"splats":[1-9]' -- render "$tmp/ok.json" --method pt-linear --small-cells splat --size 8x6 -o "$tmp/sp.png" --stats
expect 0 '"small_cells_mode":"splat".*"splats":[1-9]' -- render "$tmp/ok.json" --method slicing --small-cells splat --slices 4 --size 32x24 -o "$tmp/sps.png" --stats
"$exe" render "$tmp/ok.json" --size 32x24 -o "$tmp/a.png" --npy "$tmp/a.npy" >/dev/null 2>&1
"$exe" render "$tmp/ok.json" --size 64x48 -o "$tmp/b.png" --npy "$tmp/b.npy" >/dev/null 2>&1
expect 0 '"rmse"' -- compare "$tmp/a.npy" "$tmp/b.npy" --downsample 2
expect 1 "b.npy: downsample: 3 does not divide the image's 64x48" -- compare "$tmp/a.npy" "$tmp/b.npy" --downsample 3
if [ "$gl" = ON ]; then
  expect 2 "--small-cells splat needs the software back end" -- render "$tmp/ok.json" --method pt-linear --backend opengl --small-cells splat --size 32x24
  expect 2 "the OpenGL back ends draw --slice-integral sampled" -- render "$tmp/ok.json" --method slicing --backend opengl --size 32x24
  expect 0 '"backend":"opengl-8bit-dither".*"gl_renderer"' -- render "$tmp/ok.json" --method slicing --slice-integral sampled --backend opengl-8bit-dither --size 32x24 -o "$tmp/slgl.png" --stats
else
  expect 3 "OpenGL back ends were not built" -- render "$tmp/ok.json" --method slicing --slice-integral sampled --backend opengl --size 32x24
fi

# info --json: the documented keys with this mesh's values.
"$exe" info "$tmp/box.vtu" --json > "$tmp/info.json" || { echo "FAIL: info --json"; failed=$((failed+1)); }
python3 - "$tmp/info.json" <<'PY' || failed=$((failed+1))
import json, sys
j = json.load(open(sys.argv[1]))
want = {"points": 125, "cells": 64, "boundary_faces": 96, "convex": True, "nonplanar_faces": 0,
        "degenerate_cells": 0, "inverted_cells": 0}
bad = {k: (j.get(k), v) for k, v in want.items() if j.get(k) != v}
bad.update({k: "missing" for k in ("bounds", "fields", "cells_by_type") if k not in j})
if j["cells_by_type"] != {"tetra": 0, "hexahedron": 64, "wedge": 0, "pyramid": 0}: bad["cells_by_type"] = j["cells_by_type"]
if j["fields"]["scalar"][1] != 1.0: bad["fields"] = j["fields"]
if bad: print("FAIL: info --json", bad); sys.exit(1)
PY
# A mesh without a scene (docs/cli.md, "A first picture"): bad looks are usage errors, and the
# scene `cellproj scene` writes renders the same bits as the mesh given directly.
expect 2 "--view: unknown view 'up'" -- render "$tmp/box.vtu" --view up --size 32x24
expect 2 "--colormap: unknown colour map 'nope'" -- render "$tmp/box.vtu" --colormap nope --size 32x24
expect 2 "--opacity: expected auto, ramp, reverse, flat, sigmoid, geometric or S=DEPTH" -- render "$tmp/box.vtu" --opacity 0.5=x --size 32x24
expect 2 "--depth: expected a positive optical depth" -- render "$tmp/box.vtu" --depth -1 --size 32x24
expect 2 "--background: expected R,G,B" -- render "$tmp/box.vtu" --background 2,0,0 --size 32x24
expect 2 "is a scene file: edit its transfer_function" -- render "$tmp/ok.json" --opacity flat
expect 2 "a frame pattern takes one %d" -- render "$tmp/box.vtu" -o "$tmp/f%s.png" --frames 2
expect 2 "needs --frames N" -- render "$tmp/box.vtu" -o "$tmp/f%03d.png"
expect 2 "--orbit turns the camera over --frames" -- render "$tmp/box.vtu" --orbit 90
expect 2 "--orbit: expected a finite angle in degrees, got nan" -- render "$tmp/box.vtu" --orbit nan --frames 3
# Number options: one line naming the value and what it must be (not CLI11's range up to DBL_MAX), nan refused.
for v in 0 -1 nan inf abc; do
  expect 2 "^--max-memory: expected a finite number > 0 \\(GiB\\), got '$v'$" -- render "$tmp/box.vtu" --max-memory $v
done
expect 2 "^--max-memory: expected a finite number > 0" -- info "$tmp/box.vtu" --max-memory 0
expect 2 "^--scale: expected a finite number > 0 \\(a gain\\), got 'nan'" -- compare "$tmp/ok.npy" "$tmp/ok.npy" --scale nan
expect 2 "^--time-step: Value -1 not in range 0 to 2147483647" -- info "$tmp/box.vtu" --time-step -1
expect 2 "--splat-threshold: must be a finite number >= 0, not nan" -- render "$tmp/box.vtu" --splat-threshold nan
expect 2 "^--format: unknown format 'nope' \\(known: vtk-xml, vtk-legacy, exodus" -- info "$tmp/box.vtu" --format nope
expect 2 "generate: unknown kind 'nope'; the kinds are: box" -- generate nope -o "$tmp/nope.vtu"
expect 0 "wrote .*q.json" -- scene "$tmp/box.vtu" -o "$tmp/q/q.json" --view +y --colormap viridis --size 40x30
grep -q '"mesh": "../box.vtu"' "$tmp/q/q.json" || { echo "FAIL: scene names the mesh relative to it"; failed=$((failed+1)); }
expect 0 "wrote" -- render "$tmp/q/q.json" --npy "$tmp/q/a.npy"
expect 0 "wrote" -- render "$tmp/box.vtu" --view +y --colormap viridis --size 40x30 --npy "$tmp/q/b.npy"
cmp -s "$tmp/q/a.npy" "$tmp/q/b.npy" || { echo "FAIL: render MESH differs from render \$(scene MESH)"; failed=$((failed+1)); }
expect 0 "frame 3/3" -- render "$tmp/q/q.json" --orbit 360 --frames 3 -o "$tmp/turn/f_%02d.png" --legend
[ -f "$tmp/turn/f_02.png" ] || { echo "FAIL: turntable frames"; failed=$((failed+1)); }
expect 2 "--sort does not apply to --method mip, which reads --method" -- render "$tmp/ok.json" --method mip --sort mpvo
expect 0 "wrote .*mip" -- render "$tmp/box.vtu" --method mip --size 32x24 -o "$tmp/mip.png"
expect 2 "--method layers needs --iso V" -- render "$tmp/box.vtu" --method layers
expect 2 "--layer: give the layers in increasing order" -- render "$tmp/box.vtu" --method layers --iso 0.5 --layer 3,1
expect 2 "--iso does not apply to --method mip" -- render "$tmp/box.vtu" --method mip --iso 0.5
expect 0 "wrote .*layers" -- render "$tmp/box.vtu" --method layers --iso 0.5:1,0,0 --layer 1,2 --silhouettes both --size 32x24 -o "$tmp/layers.png"
# Iso-surfaces with the volume (--method exact): repeatable --iso, the modes, refused elsewhere.
expect 0 "wrote" -- render "$tmp/box.vtu" --method exact --iso 0.5:1,0,0,0.4 --iso 0.8:0,0,1,0.4 --iso-mode oit4 --volume off --size 32x24 -o "$tmp/iso.png"
expect 2 "--iso does not apply to --method pt-breakpoints" -- render "$tmp/box.vtu" --iso 0.5
expect 2 "--iso: .*opacity must be in \[0, 1\]" -- render "$tmp/box.vtu" --method exact --iso 0.5:1,0,0,2
expect 2 "--iso-mode: unknown iso-surface mode 'oit5'" -- render "$tmp/box.vtu" --method exact --iso 0.5 --iso-mode oit5
expect 2 "draws the crossings of one iso-value" -- render "$tmp/box.vtu" --method layers --iso 0.5 --iso 0.7
# A scene's iso list: what exact draws; other methods warn that they draw the volume alone.
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}, "iso": [{"value": 0.5, "color": [1, 0, 0], "opacity": 0.4}], "iso_mode": "oit3", "volume": false}' > "$tmp/isoscene.json"
expect 0 "wrote" -- render "$tmp/isoscene.json" --method exact --size 32x24 --npy "$tmp/i1.npy"
expect 0 "wrote" -- render "$tmp/ok.json" --method exact --iso 0.5:1,0,0,0.4 --iso-mode oit3 --volume off --size 32x24 --npy "$tmp/i2.npy"
cmp -s "$tmp/i1.npy" "$tmp/i2.npy" || { echo "FAIL: the scene's iso list differs from the same options"; failed=$((failed+1)); }
expect 0 "its iso-surfaces are drawn by --method exact; --method pt-breakpoints draws the volume alone" -- render "$tmp/isoscene.json" --size 16x16 -o "$tmp/i3.png"
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}, "iso": [{"value": 0.5, "opacity": 0.4}]}' > "$tmp/badiso.json"
expect 1 "badiso.json: iso\[0\].opacity: goes with \"color\"" -- render "$tmp/badiso.json" --method exact
# Clipping planes, from the command line or the scene, the same bits; bad planes refused.
expect 0 "wrote" -- render "$tmp/ok.json" --clip 0.1,0,0,1,0.5,0 --clip 0,0,0,0,0,1 --size 32x24 --npy "$tmp/c1.npy" --stats
grep -q '"clip_cells_cut"' "$tmp/err" || { echo "FAIL: --stats without the clip counts"; failed=$((failed+1)); }
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}, "clip": [{"point": [0.1, 0, 0], "normal": [1, 0.5, 0]}, {"point": [0, 0, 0], "normal": [0, 0, 1]}]}' > "$tmp/clip.json"
expect 0 "wrote" -- render "$tmp/clip.json" --size 32x24 --npy "$tmp/c2.npy"
cmp -s "$tmp/c1.npy" "$tmp/c2.npy" || { echo "FAIL: the scene's clip differs from --clip"; failed=$((failed+1)); }
expect 0 "wrote" -- render "$tmp/clip.json" --method exact --size 32x24 -o "$tmp/c3.png"
expect 2 "--clip: expected x,y,z,nx,ny,nz" -- render "$tmp/ok.json" --clip 0,0,1
expect 2 "--clip: the plane needs a finite point and a non-zero finite normal" -- render "$tmp/ok.json" --clip 0,0,0,0,0,0
expect 1 "nothing of the mesh is on the kept side of the clipping planes" -- render "$tmp/ok.json" --clip 0,0,-5,0,0,1 --size 16x16 -o "$tmp/c4.png"
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}, "clip": [{"point": [0, 0, 0]}]}' > "$tmp/badclip.json"
expect 1 "badclip.json: clip\[0\]: missing \"normal\"" -- render "$tmp/badclip.json"
# A scene's "layers" block gives what the options would; the command line overrides it.
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}, "layers": {"iso": 0.5, "color": [1, 0, 0], "layer": [1, 2], "silhouettes": "both"}}' > "$tmp/layers.json"
expect 0 "wrote" -- render "$tmp/layers.json" --method layers --size 32x24 --npy "$tmp/l1.npy"
expect 0 "wrote" -- render "$tmp/ok.json" --method layers --iso 0.5:1,0,0 --layer 1,2 --silhouettes both --size 32x24 --npy "$tmp/l2.npy"
cmp -s "$tmp/l1.npy" "$tmp/l2.npy" || { echo "FAIL: the scene's layers block differs from the same options"; failed=$((failed+1)); }
expect 0 "wrote" -- render "$tmp/layers.json" --method layers --layer 2 --size 32x24 --npy "$tmp/l3.npy"
cmp -s "$tmp/l1.npy" "$tmp/l3.npy" && { echo "FAIL: --layer did not override the scene's"; failed=$((failed+1)); }
expect 0 "wrote" -- render "$tmp/layers.json" --size 32x24 -o "$tmp/l4.png"  # other methods ignore the block
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}, "layers": {"iso": 0.5, "layer": [2, 1]}}' > "$tmp/badlayers.json"
expect 1 "badlayers.json: layers: --layer: give the layers in increasing order" -- render "$tmp/badlayers.json" --method layers
# Time series (docs/methods.md, "Time series"): playback with and without the background thread
# gives the same bits; bad times, options and key frames are refused.
expect 0 "6 key frames" -- generate box-tets -n 3 --steps 6 -o "$tmp/ser/s.pvd"
expect 0 "frame 4/4, .*time 5" -- render "$tmp/ser/s.pvd" --animate 0:5:4 --size 24x20 --npy "$tmp/ser/a_%d.npy"
expect 0 "frame 4/4" -- render "$tmp/ser/s.pvd" --animate 0:5:4 --size 24x20 --npy "$tmp/ser/b_%d.npy" --no-prefetch
for f in 0 1 2 3; do cmp -s "$tmp/ser/a_$f.npy" "$tmp/ser/b_$f.npy" || { echo "FAIL: prefetch changed frame $f"; failed=$((failed+1)); }; done
expect 0 "wrote" -- render "$tmp/ser/s.pvd" --time 5 --size 24x20 --npy "$tmp/ser/t5.npy"
expect 0 "frame 3/3" -- render "$tmp/ser/s.pvd" --animate 0:5:3 --clip 0,0,0,1,0.3,0 --size 24x20 --npy "$tmp/ser/c_%d.npy" --stats
grep -q '"clip_cells_cut":[1-9]' "$tmp/err" || { echo "FAIL: a clipped series' --stats"; failed=$((failed+1)); }
cmp -s "$tmp/ser/a_0.npy" "$tmp/ser/c_0.npy" && { echo "FAIL: --clip did not clip the series"; failed=$((failed+1)); }
cmp -s "$tmp/ser/t5.npy" "$tmp/ser/a_3.npy" || { echo "FAIL: --time 5 differs from the animation's last frame"; failed=$((failed+1)); }
expect 0 "wrote" -- render "$tmp/ser/s_%04d.vtu" --time 2.5 --size 24x20 -o "$tmp/ser/p.png"
expect 0 "s.pvd: a time series of 6 key frames, times 0.0 to 5.0" -- info "$tmp/ser/s.pvd"
expect 1 "s.pvd: time 7.000000 is outside the series' times \[0.000000, 5.000000\]" -- render "$tmp/ser/s.pvd" --time 7
# An opacity field of its own (colour by --field, extinction by --opacity-field).
expect 1 "s.pvd: --opacity-field draws one mesh's two fields, not a time series' yet" -- render "$tmp/ser/s.pvd" --opacity-field scalar -o "$tmp/ser/o.png"
expect 2 "--time renders one frame and --animate many" -- render "$tmp/ser/s.pvd" --time 1 --animate 0:1:2 -o "$tmp/ser/x_%d.png"
expect 2 "--animate: expected T0:T1:FRAMES" -- render "$tmp/ser/s.pvd" --animate 0:1
expect 1 "box.vtu: not a time series" -- render "$tmp/box.vtu" --time 1
# A pattern is given to printf: one %d and no other %, or it is refused before any use.
expect 1 "a numbered series names its files with one %d in the file name and no other %" -- render "$tmp/ser/s_%n%04d.vtu" --time 1 -o "$tmp/ser/n.png"
expect 1 "a numbered series names its files with one %d in the file name and no other %" -- generate box -n 2 --steps 2 -o "$tmp/ser/g%n%d.vtu"
expect 1 "a numbered series names its files with one %d in the file name and no other %" -- generate box -n 2 --steps 2 -o "$tmp/ser/g%s.pvd"
truncate -s 70M "$tmp/ser/big.pvd"
expect 1 "big.pvd: is 70 MiB: too large for a ParaView collection" -- render "$tmp/ser/big.pvd" -o "$tmp/ser/b.png"
rm "$tmp/ser/big.pvd"
rm "$tmp/ser/s_0003.vtu"
expect 1 "s_0003.vtu: no such file" -- render "$tmp/ser/s.pvd" --time 2.5
# docs/reliability.md: bad files of every kind get exit 1 and a message naming file and element.
mkdir -p "$tmp/afolder" "$tmp/afolder.json"
expect 1 "afolder: is a folder, not a mesh file" -- render "$tmp/afolder"  # no .json: taken as a mesh
expect 1 "afolder.json: is a folder, not a scene file" -- render "$tmp/afolder.json"
expect 1 "afolder: is a folder, not a mesh file" -- info "$tmp/afolder"
expect 1 "nosuch.json: no such scene file" -- render "$tmp/nosuch.json"
expect 0 "wrote .*new/sub/box.vtk" -- generate box -n 2 -o "$tmp/new/sub/box.vtk"
expect 1 "x.vtu: cannot be written" -- generate box -n 2 -o /proc/x.vtu
expect 1 "a.stl: cannot write '.stl' files" -- generate box -n 2 -o "$tmp/a.stl"
# Paths the file system refuses to look up or to make (std::filesystem's own errors were "internal
# errors", exit 3; the scene fuzzer found the first): a name too long, a folder under a file.
long=$(printf 'n%.0s' {1..300})
echo "{\"mesh\": \"$long.vtu\", \"transfer_function\": {\"color\": [[0, 1, 1, 1]], \"extinction\": [[0, 1]]}}" > "$tmp/long.json"
expect 1 "$long.vtu: cannot be looked up \\(File name too long\\)" -- render "$tmp/long.json"
expect 1 "$long.vtu: cannot be looked up \\(File name too long\\)" -- info "$tmp/$long.vtu"
touch "$tmp/plain"
expect 1 "plain: is not a folder: .*x.png cannot be written" -- render "$tmp/ok.json" -o "$tmp/plain/x.png"
expect 1 "plain/x: no such folder for .*y.npy" -- render "$tmp/ok.json" --npy "$tmp/plain/x/y.npy"
expect 1 "nodir: no such folder for .*x.png \\(only a --frames pattern makes its folder\\)" -- render "$tmp/ok.json" -o "$tmp/nodir/x.png"
expect 1 "plain: cannot create the folder \\(Not a directory\\)" -- render "$tmp/ok.json" --frames 2 -o "$tmp/plain/f_%02d.png"
expect 1 "plain: cannot create the folder" -- scene "$tmp/box.vtu" -o "$tmp/plain/s.json"
printf '4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 nan 0\n4 0 0 1\n' > "$tmp/t.node"; printf '1 4 0\n1 1 2 3 4\n' > "$tmp/t.ele"
expect 1 "t.node: line 4: point 3 has a non-finite coordinate" -- info "$tmp/t.node"
printf '4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n' > "$tmp/t.node"; printf '1 4 0\n1 1 2 3 -7\n' > "$tmp/t.ele"
expect 1 "t.ele: line 2: tetrahedron 0 refers to point -7, out of range \[1, 5\)" -- info "$tmp/t.node"
printf '1 4 0\n1 1 2\n3 4\n' > "$tmp/t.ele"
expect 1 "t.ele: line 2: the record ends where a point id was expected" -- info "$tmp/t.node"
printf '# vtk DataFile Version 3.0\nx\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 2000000000 double\n' > "$tmp/huge.vtk"
expect 1 "huge.vtk: its header declares 2000000000 points and 0 cells: reading them needs about [0-9.]+ GiB, more than the 4.0 GiB allowed by --max-memory" -- info "$tmp/huge.vtk" --max-memory 4
expect 1 "huge.vtk: its header declares" -- sortbench "$tmp/huge.vtk" --max-memory 4
expect 2 "--progressive renders one view" -- render "$tmp/ok.json" --method slicing --progressive 8,16 --frames 2
# A camera that sees nothing of the mesh says so; an orthographic eye inside the mesh too.
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}, "camera": {"projection": "perspective", "eye": [0, 0, 5], "target": [0, 0, 10], "up": [0, 1, 0]}}' > "$tmp/away.json"
expect 0 "away.json: nothing of the mesh is in view: it lies wholly behind the camera" -- render "$tmp/away.json" --size 16x16 -o "$tmp/away.png"
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}, "camera": {"projection": "perspective", "eye": [0, 0, 5], "target": [5, 0, 3], "up": [0, 1, 0], "fov_y": 20}}' > "$tmp/side.json"
expect 0 "side.json: nothing of the mesh is in view: its bounding box lies outside the camera's field of view" -- render "$tmp/side.json" --size 16x16 -o "$tmp/side.png"
echo '{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}, "camera": {"projection": "orthographic", "eye": [0, 0, 0], "target": [0, 0, -1], "up": [0, 1, 0]}}' > "$tmp/oin.json"
expect 0 "oin.json: part of the mesh lies behind the orthographic camera's eye plane" -- render "$tmp/oin.json" --size 16x16 -o "$tmp/oin.png"
"$exe" render "$tmp/ok.json" --size 16x16 -o "$tmp/ok3.png" 2>"$tmp/err" >/dev/null
! grep -q "in view\|eye plane" "$tmp/err" || { echo "FAIL: the default camera sees the mesh, yet render warns"; failed=$((failed+1)); }
# Exodus cut in half: called truncated, not corrupt connectivity (netCDF reads fill values past the end);
# cut by 64 bytes, inside the field's values: truncated too, not a field of zeros.
"$exe" generate mixed -n 2 -o "$tmp/m.exo" >/dev/null && head -c $(( $(stat -c %s "$tmp/m.exo") / 2 )) "$tmp/m.exo" > "$tmp/half.exo"
expect 1 "half.exo: truncated: the header places variable '[a-z_0-9]+' up to byte [0-9]+, the file has [0-9]+ bytes" -- info "$tmp/half.exo"
head -c $(( $(stat -c %s "$tmp/m.exo") - 64 )) "$tmp/m.exo" > "$tmp/short.exo"
expect 1 "short.exo: truncated: the header places variable 'vals_nod_var1' up to byte [0-9]+, the file has [0-9]+ bytes" -- info "$tmp/short.exo"
expect 0 "points 29, cells 26" -- info "$tmp/m.exo"
sed 's/num_el_in_blk2/num_el_in_blk0/' "$tmp/m.exo" >"$tmp/block.exo"  # VTK's Exodus reader crashed on it
expect 1 "block.exo: corrupt: element block 2 of 4 has no dimension 'num_el_in_blk2'" -- info "$tmp/block.exo"
python3 -c "import sys; b=bytearray(open(sys.argv[1],'rb').read()); j=b.index(b'num_nodes')+12; b[j:j+4]=(2000000000).to_bytes(4,'big'); open(sys.argv[2],'wb').write(b)" "$tmp/m.exo" "$tmp/huge.exo"
expect 1 "huge.exo: its header declares 2000000000 points and 26 cells: reading them needs about [0-9.]+ GiB, more than the 4.0 GiB allowed by --max-memory" -- info "$tmp/huge.exo" --max-memory 4
# A legacy file whose cell is a polyhedron (42): the cell type is named, not a miscounted truncation.
"$exe" generate box-tets -n 1 -o "$tmp/t.vtk" >/dev/null && awk 'f&&/^10$/&&!d{print "42";d=1;next} /CELL_TYPES/{f=1} {print}' "$tmp/t.vtk" >"$tmp/poly.vtk"
expect 1 "poly.vtk: unsupported cell types: polyhedron \\(42\\): 1 cells \\(first: cell 0\\)" -- info "$tmp/poly.vtk"
# VTK keeps a cell type's low byte: 298 is a polyhedron to it too (fuzzed binary files whose type
# 1847604522 crashed it decomposing a face stream).
cp "$src/tests/fuzz/regressions/vtk/crash-cbc1cf98f413ed89dce4a7c9f1db93cf9e018a23" "$tmp/polybyte.vtk"
expect 1 "polybyte.vtk: unsupported cell types: polyhedron \\(42\\): 1 cells \\(first: cell 18\\)" -- info "$tmp/polybyte.vtk"
# A binary format-5 file whose cell 24 became a polyhedron (a fuzzer's input that crashed VTK's
# reader decomposing the garbled face stream): refused by the walk before VTK reads it.
cp "$src/tests/fuzz/regressions/vtk/crash-3b40acd17da3c8afce31a4d129bae16e4eab1245" "$tmp/poly5.vtk"
expect 1 "poly5.vtk: unsupported cell types: polyhedron \\(42\\): 1 cells \\(first: cell 24\\)" -- info "$tmp/poly5.vtk"
# A negative count (VTK's binary reader took it as a huge size and wrote past its array).
printf '# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS -3 double\n0 0 0\n' > "$tmp/neg.vtk"
expect 1 "neg.vtk: POINTS declares a negative count \\(-3\\)" -- info "$tmp/neg.vtk"
# Fuzzed binary files that crashed VTK's reader: "bINARY" on the third line (binary to VTK, so the
# CELLS block read as the older layout is checked as such), and a format-5 offset far past the
# connectivity (VTK's SetCells walked it).
cp "$src/tests/fuzz/regressions/vtk/crash-9945fbdb17b39809e79bb1da5b75f1c25eb2d6a9" "$tmp/lower.vtk"
expect 1 "lower.vtk: cell 0 has 1330005587 points, more than the 135 numbers left in the CELLS block \\(27 cells, 136 numbers\\)" -- info "$tmp/lower.vtk"
cp "$src/tests/fuzz/regressions/vtk/crash-c8ce9a162e423c81a64b094b4dda8261c2bdc275" "$tmp/offset.vtk"
expect 1 "offset.vtk: cell 13's point ids run from offset 68 to 1095216660556, outside the 136 connectivity ids or backwards" -- info "$tmp/offset.vtk"
# A message quoting a garbled file's bytes (VTK's "Unrecognized keyword" of binary data) reaches
# the terminal with them written as \xNN; a file name in UTF-8 passes unchanged.
cp "$src/tests/fuzz/regressions/vtk/crash-5aa79bf15d3f259fdd0be3011fcb804da059ef26" "$tmp/sgc.vtk"
expect 1 "sgc.vtk: cannot be read: Unrecognized keyword: \\\\xF0$" -- info "$tmp/sgc.vtk"
expect 1 "café.vtu: no such file" -- info "$tmp/café.vtu"
# VTK takes a line starting "METADATA" after an array for metadata and ends it at a line starting
# with a NUL byte, then reads on: the walk follows it there to the CELLS block (a fuzzed file whose
# block of 0 numbers for 1417395 cells crashed VTK).
cp "$src/tests/fuzz/regressions/vtk/crash-10c78117cc34acbf73718a48209bc61862a5a5a3" "$tmp/meta.vtk"
expect 1 "meta.vtk: the CELLS block \\(1417395 cells, 0 numbers\\) cannot give each cell its count" -- info "$tmp/meta.vtk"
# POINTS typed as strings ("stringdouble": VTK matches the prefix): VTK's string reader wrote past
# its buffer on it (AddressSanitizer, in a fuzz run); coordinates are numbers.
cp "$src/tests/fuzz/regressions/vtk/crash-6780a877e5b19815aaf4e6753cc85b22d0644115" "$tmp/strpts.vtk"
expect 1 "strpts.vtk: POINTS has the type 'stringdouble', which VTK reads as strings: coordinates are numbers" -- info "$tmp/strpts.vtk"
# A classic netCDF (Exodus) header declaring 16 million dimensions in a 183-byte file: netCDF sized
# its hash map by the count (out of memory in a fuzz run, "Argument list too long" here before).
cp "$src/tests/fuzz/regressions/exodus/crash-a74af697e3c6b5a64ae19e308f1bbdf91b187dd4" "$tmp/dims.exo"
expect 1 "dims.exo: corrupt: its header declares 16777216 dimensions at byte 16, more than the 167 bytes after it can hold" -- info "$tmp/dims.exo"
# A variable of type 12 (netCDF-4's string) in a classic file: netCDF divided by its size, 0, while
# opening it (a floating-point exception in a fuzz run).
cp "$src/tests/fuzz/regressions/exodus/crash-f011fcb3e88d9105a76805b3c250a9105505be84" "$tmp/type.exo"
expect 1 "type.exo: corrupt: variable 'eb_prop1' has the unknown type 12" -- info "$tmp/type.exo"
# Element block ids all 0 (VTK's reader crashed in BuildSIL), and a maximum_name_length of 0
# (netCDF wrote names past the buffers VTK sized by it): fuzz inputs.
cp "$src/tests/fuzz/regressions/exodus/crash-6ca593643c7d652ff6abfb7d9b4240c500866b9c" "$tmp/ids.exo"
expect 1 "ids.exo: corrupt: element blocks 1 and 2 both have the id 0 \\('eb_prop1'\\); ids must be unique" -- info "$tmp/ids.exo"
cp "$src/tests/fuzz/regressions/exodus/crash-86d96a60e213e0de1b3b1c1a851a698d3576a558" "$tmp/names.exo"
expect 1 "names.exo: corrupt: its attribute 'maximum_name_length' is 0, outside \\[1, 256\\]" -- info "$tmp/names.exo"
# A HEX block of 5 nodes per element (VTK's reader read hexahedra of 8 past the block), and a
# record count of 2^32 - 1 in a 5 kB file (our own check sized a buffer by it: "out of memory").
# A 15-byte classic netCDF file cut inside its header: netCDF read zero-filled dimensions past the
# end for 15 s before it gave up.
cp "$src/tests/fuzz/regressions/exodus/slow-unit-f55ffdc3852d1fbcb9dd7c3eec681903854a09d1" "$tmp/cut15.exo"
expect 1 "cut15.exo: corrupt: its classic netCDF header is cut short: the file ends at byte 15, inside it" -- info "$tmp/cut15.exo"
cp "$src/tests/fuzz/regressions/exodus/crash-6de9d79f8f819eeeeff2c85c8d71ef1b508be8a2" "$tmp/hex5.exo"
expect 1 "hex5.exo: corrupt: element block 2 of 4: its elements of type 'HEX' have 5 nodes each \\(num_nod_per_el2\\); VTK's Exodus reader reads that type with 8, 20 or 27" -- info "$tmp/hex5.exo"
cp "$src/tests/fuzz/regressions/exodus/crash-eff4922f02b1491bd0e700e4ecf90f4a0f4a10fa" "$tmp/records.exo"
expect 1 "records.exo: corrupt: variable 'time_whole' declares 4294967295 values of 8 bytes, more than the file's 5072 bytes hold" -- info "$tmp/records.exo"
# A fuzzer's binary file whose POINT_DATA holds a FIELD array of -9 tuples (VTK's reader sized the
# array with it and wrote past it), and a structured grid with an array named field_strength (VTK
# 9.1's metadata pass took the name for a FIELD block and crashed on a good file).
cp "$src/tests/fuzz/regressions/vtk/crash-c7982eb7bfd2cd5f09bb3141237137c87a46210b" "$tmp/negfield.vtk"
expect 1 "negfield.vtk: POINT_DATA's FIELD block 'FieldData', array 0 \\('scalar'\\): a negative count \\(1 components of -9 tuples\\)" -- info "$tmp/negfield.vtk"
printf '# vtk DataFile Version 3.0\nsg\nASCII\nDATASET STRUCTURED_GRID\nDIMENSIONS 2 2 2\nPOINTS 8 float\n0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1\nPOINT_DATA 8\nSCALARS field_strength float 1\nLOOKUP_TABLE default\n0 1 2 3 4 5 6 7\n' >"$tmp/sg.vtk"
expect 0 "points 8, cells 1: hexahedron 1" -- info "$tmp/sg.vtk"
# A rectilinear grid's axis with fewer coordinates than DIMENSIONS gives (VTK's reader took the
# missing ones from past its array: y up to 3e-41 and exit 0), and POLYDATA, whose out-of-range
# polygon ids crashed VTK's reader though it holds no volume cells.
printf '# vtk DataFile Version 3.0\nrg\nASCII\nDATASET RECTILINEAR_GRID\nDIMENSIONS 2 2 2\nX_COORDINATES 2 float\n0 1\nY_COORDINATES 1 float\n0\nZ_COORDINATES 2 float\n0 1\nPOINT_DATA 8\nSCALARS s float 1\nLOOKUP_TABLE default\n0 1 2 3 4 5 6 7\n' >"$tmp/rg.vtk"
expect 1 "rg.vtk: Y_COORDINATES holds 1 values for the 2 points along its axis that DIMENSIONS gives" -- info "$tmp/rg.vtk"
sed 's/^Y_COORDINATES 1 float$/Y_COORDINATES 2 float/; s/^0$/0 1/' "$tmp/rg.vtk" >"$tmp/rg2.vtk"
expect 0 "points 8, cells 1: hexahedron 1" -- info "$tmp/rg2.vtk"
# A grid whose DIMENSIONS or EXTENT give an axis fewer than one point: a rectilinear grid's ended in
# VTK's std::length_error (exit 3), a structured grid's read as no cells at all.
sed 's/^DIMENSIONS 2 2 2$/DIMENSIONS 2 -2 2/' "$tmp/rg2.vtk" >"$tmp/rgneg.vtk"
expect 1 "rgneg.vtk: DIMENSIONS gives -2 points along y: a grid has at least one point along each axis" -- info "$tmp/rgneg.vtk"
sed 's/^DIMENSIONS 2 2 2$/DIMENSIONS -2 2 2/' "$tmp/sg.vtk" >"$tmp/sgneg.vtk"
expect 1 "sgneg.vtk: DIMENSIONS gives -2 points along x" -- info "$tmp/sgneg.vtk"
printf '# vtk DataFile Version 3.0\npd\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 7\n' >"$tmp/pd.vtk"
expect 1 "pd.vtk: its dataset is POLYDATA \\(surfaces, lines and points\\), which holds no volume cells" -- info "$tmp/pd.vtk"
# A fuzzed .vtu whose offsets array says format="appe": VTK read it as appended, and its garbled
# compression header sized 16 GB (95 s and 16 GB before the address-space limit stopped it).
cp "$src/tests/fuzz/regressions/vtu/crash-6d88ac0e517ccc57f7fcba81c76df9f7fd358354" "$tmp/appe.vtu"
expect 1 "appe.vtu: DataArray 'offsets' \\(appended at offset 808\\): its compression header runs past the end of its data, or is not base64" -- info "$tmp/appe.vtu"
# A fuzzed .vtu whose AppendedData lost its '_': VTK's reader looked for its data for 13 to 97 s and
# asked for 20 GB.
cp "$src/tests/fuzz/regressions/vtu/crash-ca079d298646bd75ab4a6c7babb37e84173afd11" "$tmp/nounderscore.vtu"
expect 1 "nounderscore.vtu: its AppendedData section does not begin with '_' \\(byte 1297\\): where its arrays' offsets count from is unknown" -- info "$tmp/nounderscore.vtu"
# Geomview's OFF, a surface, shares the .off extension with the tetrahedral benchmark format.
printf 'OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n' >"$tmp/geomview.off"
expect 1 "geomview.off: line 1: 'OFF' starts a Geomview OFF surface \\(polygons\\)" -- info "$tmp/geomview.off"
printf '# vtk DataFile Version 3.0\nsp\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2000 2000 2000\nORIGIN 0 0 0\nSPACING 1 1 1\n' >"$tmp/sp.vtk"
expect 1 "sp.vtk: its header declares 8000000000 points and 7988005999 cells: reading them needs about [0-9.]+ GiB, more than the 4.0 GiB allowed by --max-memory" -- info "$tmp/sp.vtk" --max-memory 4
# Legacy .vtk structure VTK's reader follows without bounds: a cell count past the CELLS block, a
# garbled version line (a format-5 body read as the older layout), offsets pointing anywhere.
printf '# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n9 0 1 2 3\nCELL_TYPES 1\n10\n' >"$tmp/count.vtk"
expect 1 "count.vtk: cell 0 has 9 points, more than the 4 numbers left in the CELLS block \\(1 cells, 5 numbers\\)" -- info "$tmp/count.vtk"
# VTK finds the block as a word starting with "cells" in any case, after any whitespace (fuzzed
# files that crashed it: "CELLSPOINT_", "cELLS", a vertical tab before the line).
for kw in 'CELLSPOINT_' 'cELLS' '\vCELLS'; do
  sed "s/^CELLS/$kw/" "$tmp/count.vtk" >"$tmp/count2.vtk"
  expect 1 "count2.vtk: cell 0 has 9 points, more than the 4 numbers left in the CELLS block \\(1 cells, 5 numbers\\)" -- info "$tmp/count2.vtk"
done
# VTK takes the encoding as the first word after the title, past blank lines (a fuzzed file with a
# blank third line: the checks took the encoding for unknown, and VTK's reader crashed on its CELLS).
printf '# vtk DataFile Version 3.0\nt\n\n  \nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n9 0 1 2 3\nCELL_TYPES 1\n10\n' >"$tmp/blank.vtk"
expect 1 "blank.vtk: cell 0 has 9 points, more than the 4 numbers left in the CELLS block \\(1 cells, 5 numbers\\)" -- info "$tmp/blank.vtk"
sed 's/Version 5.1/Version 5x1/' "$tmp/t.vtk" >"$tmp/version.vtk"
expect 1 "version.vtk: line 1: the version is garbled" -- info "$tmp/version.vtk"
# A format-5 CONNECTIVITY one id short: VTK's reader read it with exit 0 and degenerate cells; a
# fuzzed file's short OFFSETS crashed it.
awk '/^CONNECTIVITY/{print; getline; $1=""; print; next} {print}' "$tmp/t.vtk" >"$tmp/shortconn.vtk"
expect 1 "shortconn.vtk: CELLS 7 24: its CONNECTIVITY array holds 23 numbers where the block declares 24: truncated or corrupt" -- info "$tmp/shortconn.vtk"
awk '/^OFFSETS/{print; getline; $1=""; print; next} {print}' "$tmp/t.vtk" >"$tmp/shortoff.vtk"
expect 1 "shortoff.vtk: CELLS 7 24: its OFFSETS array holds 6 numbers where the block declares 7: truncated or corrupt" -- info "$tmp/shortoff.vtk"
awk '/^OFFSETS/{print; getline; $2=99; print; next} {print}' "$tmp/t.vtk" >"$tmp/offsets.vtk"
expect 1 "offsets.vtk: cell 0's point ids run from offset 0 to 99, outside the [0-9]+ connectivity ids or backwards" -- info "$tmp/offsets.vtk"
# An .off count behind a comment: the header check reads it as the reader does.
printf '822222212 # a garbled count\n6\n0 0 0 1\n' >"$tmp/count.off"
expect 1 "count.off: its header declares 822222212 points and 6 cells: reading them needs about [0-9.]+ GiB, more than the 4.0 GiB allowed by --max-memory" -- info "$tmp/count.off" --max-memory 4
# A number beyond a double in a scene: named as the scene file's JSON error, like a syntax error.
echo '{"mesh": "box.vtu", "camera": {"height": 8e898}}' >"$tmp/big.json"
expect 1 "big.json: not valid JSON .*number overflow" -- render "$tmp/big.json"
# Partitioning (issue 18): bad counts, a missing mesh, a malformed index; a partition index renders
# in one process as well (the single-machine path).
expect 2 "bricks" -- partition "$tmp/box.vtu" --bricks 0 -o "$tmp/parts"
expect 1 "missing.vtu: no such file" -- partition "$tmp/missing.vtu" --bricks 2 -o "$tmp/parts"
expect 2 "cost" -- partition "$tmp/box.vtu" --bricks 2 --cost volume -o "$tmp/parts"
expect 1 "box.vtu: partitioning 64 cells \(the mesh and one brick\) needs about .* more than the .*--max-memory" -- partition "$tmp/box.vtu" --bricks 2 --max-memory 0.000001 -o "$tmp/parts"
expect 0 "wrote .*parts/partition.json \(3 bricks" -- partition "$tmp/box.vtu" --bricks 3 -o "$tmp/parts"
expect 0 "wrote .*parts.png \(32x24, pt-breakpoints, 1 rank" -- render "$tmp/parts" --size 32x24 -o "$tmp/parts.png"
expect 0 "partition of .*box.vtu: 64 cells into 3 bricks" -- info "$tmp/parts"
expect 2 "renders one mesh: --progressive, --time and --animate" -- render "$tmp/parts" --time 1
expect 2 "composites the bricks' pictures in depth order, and this method takes one value of each whole ray" -- render "$tmp/parts" --method mip
expect 2 "blends iso-surfaces out of depth order" -- render "$tmp/parts" --method exact --iso 0.5 --iso-mode oit3
expect 2 "clipping planes do not go with a partition index" -- render "$tmp/parts" --clip 0,0,0,1,0,0
cp "$tmp/parts/partition.json" "$tmp/parts/good.json"
sed 's/"brick": 2/"brick": 1/' "$tmp/parts/good.json" > "$tmp/parts/partition.json"
expect 1 "partition.json: .*names brick 1: out of range or named twice" -- render "$tmp/parts"
sed 's/"cellproj_partition": 1/"cellproj_partition": 7/' "$tmp/parts/good.json" > "$tmp/parts/partition.json"
expect 1 "partition.json: not a cellproj partition index" -- render "$tmp/parts"
printf '{"cellproj_partition": 1, "source": "x"' > "$tmp/parts/partition.json"
expect 1 "partition.json: malformed partition index" -- render "$tmp/parts"
# Several volumes in one scene (docs/scene.md, "Several volumes"): drawn by exact (the default there),
# a volume list of one is the ordinary scene, and what does not go with several volumes is refused.
"$exe" generate box-tets -n 3 -o "$tmp/bt.vtu" >/dev/null
echo '{"volumes": [{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 0.5, 0]], "extinction": [[0, 1]]}}, {"mesh": "bt.vtu", "transfer_function": {"color": [[0, 0, 0.5, 1]], "extinction": [[0, 2]]}, "iso": [{"value": 0.5, "color": [1, 0, 0], "opacity": 0.5}]}], "iso_mode": "oit4"}' > "$tmp/two.json"
expect 0 "wrote .*two.png \(32x24, 2 volumes, exact" -- render "$tmp/two.json" --size 32x24 -o "$tmp/two.png" --stats
grep -q '"overlap_pieces":[1-9]' "$tmp/err" && grep -q '"iso_mode":"oit4"' "$tmp/err" || { echo "FAIL: --stats of two volumes"; failed=$((failed+1)); }
expect 0 "wrote" -- render "$tmp/two.json" --size 32x24 -o "$tmp/two_o.png" --frames 2 --orbit 90 --clip 0,0,0,1,0,0 --iso-mode ordered --volume off
# --outline on several volumes outlines their common box: the pixels it changes span the picture,
# not a dot at the origin (a box of zero size).
expect 0 "wrote" -- render "$tmp/two.json" --size 64x48 -o "$tmp/two_plain.png"
expect 0 "wrote" -- render "$tmp/two.json" --size 64x48 -o "$tmp/two_outline.png" --outline
python3 - "$tmp/two_plain.png" "$tmp/two_outline.png" <<'PY' || { echo "FAIL: --outline of two volumes"; failed=$((failed+1)); }
import struct, sys, zlib
def rgb_rows(path):  # an 8-bit RGB PNG, filters undone
    data = open(path, "rb").read()
    w, h = struct.unpack(">II", data[16:24]); pos, idat = 8, b""
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        idat += data[pos + 8:pos + 8 + n] if kind == b"IDAT" else b""; pos += 12 + n
    raw, rows, stride = zlib.decompress(idat), [], 3 * w
    for j in range(h):
        f, line = raw[j * (stride + 1)], bytearray(raw[j * (stride + 1) + 1:(j + 1) * (stride + 1)])
        prev = rows[-1] if rows else bytearray(stride)
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0; b = prev[i]; c = prev[i - 3] if i >= 3 else 0
            p = a + b - c; pr = a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else b if abs(p - b) <= abs(p - c) else c
            line[i] = (line[i] + [0, a, b, (a + b) // 2, pr][f]) & 255
        rows.append(line)
    return w, rows
w, plain = rgb_rows(sys.argv[1]); _, lined = rgb_rows(sys.argv[2])
xs = [i // 3 for r0, r1 in zip(plain, lined) for i in range(len(r0)) if r0[i] != r1[i]]
sys.exit(0 if xs and max(xs) - min(xs) >= w // 2 else 1)
PY
expect 2 "--method pt-linear draws one mesh; .*two.json has 2 volumes, drawn together by --method exact" -- render "$tmp/two.json" --method pt-linear
expect 2 "--iso: .*two.json has 2 volumes: give each volume's iso-surfaces in its \"iso\" list" -- render "$tmp/two.json" --iso 0.3
expect 2 "--field: .*two.json has 2 volumes" -- render "$tmp/two.json" --field scalar
expect 2 "--time and --animate: .*two.json has 2 volumes" -- render "$tmp/two.json" --time 1
sed 's/"bt.vtu"/"nothere.vtu"/' "$tmp/two.json" > "$tmp/missing2.json"
expect 1 "nothere.vtu: no such file" -- render "$tmp/missing2.json"
sed 's/"iso_mode": "oit4"/"mesh": "box.vtu"/' "$tmp/two.json" > "$tmp/both.json"
expect 1 "both.json: mesh: with a \"volumes\" list, give it inside each volume" -- render "$tmp/both.json"
sed 's/"opacity": 0.5/"opacity": 5/' "$tmp/two.json" > "$tmp/badvol.json"
expect 1 "badvol.json: volumes\[1\]: --iso: the opacity must be in \[0, 1\]" -- render "$tmp/badvol.json"
expect 1 "nothing of the volumes is on the kept side" -- render "$tmp/two.json" --clip 0,0,-5,0,0,1 --size 16x16 -o "$tmp/c5.png"
"$exe" generate swirl -n 3 -o "$tmp/ring.vtu" >/dev/null
echo '{"volumes": [{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 0.5, 0]], "extinction": [[0, 1]]}}, {"mesh": "ring.vtu", "transfer_function": {"color": [[0, 0, 0.5, 1]], "extinction": [[0, 2]]}}], "clip": [{"point": [0, 0, 0.6], "normal": [0, 0, -1]}]}' > "$tmp/cut2.json"
expect 0 "volumes\\[1\\] \\(.*ring.vtu\\): nothing of it is on the kept side of the clipping planes; it is left out" -- render "$tmp/cut2.json" --size 16x16 -o "$tmp/c6.png"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
