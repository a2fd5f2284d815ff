#!/usr/bin/env bash
# Distributed rendering (issue 18) through the command line under mpirun: for P = 1..4 ranks and
# several brick counts, the picture of the bricks equals the single process's picture of the whole
# mesh to 1e-6 (max abs), on a non-convex curvilinear grid of hexahedra (swirl), a mixed-element
# mesh and a graded tetrahedral one, orthographic and perspective, with the eye inside some bricks.
# The methods compared with the whole mesh are those exact for the canonical tetrahedra (exact on
# them, pt-breakpoints with every cell split); every method is compared with its own P = 1 picture.
# Then bad input: a missing and a truncated brick (every rank exits non-zero, the error names rank
# and file, no hang), more ranks than bricks.
# usage: mpi_render.sh CELLPROJ PYTHON [quick]   (quick: one mesh and 1 or 3 ranks, for the sanitizer build)
set -u
exe=$1; py=${2:-python3}; quick=${3:-}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # CI containers run as root
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl=self,vader  # a 2-core machine, one node
failed=0; passed=0
fail() { echo "FAIL: $*"; failed=$((failed+1)); }
mpi() { local p=$1; shift; timeout 120 mpirun --oversubscribe -np "$p" "$exe" "$@"; }

# max_abs of two .npy images is at most $3.
same() {
  local d; d=$("$exe" compare "$1" "$2") || { fail "compare $1 $2"; return; }
  if "$py" -c "import json,sys; sys.exit(0 if json.loads(sys.argv[1])['max_abs'] <= float(sys.argv[2]) else 1)" "$d" "$3"
  then passed=$((passed+1)); else fail "$4: $d (want max_abs <= $3)"; fi
}

# scene MESH NAME CAMERA_JSON: a scene of MESH (its default look) with the given camera.
scene() {
  "$exe" scene "$tmp/$1.vtu" -o "$tmp/$2.json" >/dev/null 2>&1 || fail "scene $1"
  "$py" - "$tmp/$2.json" "$3" <<'EOF'
import json, sys
s = json.load(open(sys.argv[1])); s["camera"] = json.loads(sys.argv[2]); s["image"] = {"width": 72, "height": 64}
json.dump(s, open(sys.argv[1], "w"))
EOF
}
with_mesh() {  # with_mesh SCENE MESH OUT: SCENE rendering MESH instead
  "$py" -c "import json,sys; s=json.load(open(sys.argv[1])); s['mesh']=sys.argv[2]; json.dump(s, open(sys.argv[3],'w'))" "$1" "$2" "$3"
}

ortho='{"projection": "orthographic", "eye": [2.1, 1.7, 3.5], "target": [0, 0, 0], "up": [0, 1, 0], "height": 3.2}'
persp='{"projection": "perspective", "eye": [-2.5, 3.0, -1.6], "target": [0, 0, 0], "up": [0, 0, 1], "fov_y": 50}'
inside='{"projection": "perspective", "eye": [0.35, 0.2, 0.1], "target": [-1, -0.4, -0.2], "up": [0, 0, 1], "fov_y": 80}'

meshes="swirl mixed graded-tets"; ranks="1 2 3 4"
[ -n "$quick" ] && meshes="mixed" && ranks="1 3"
for mesh in $meshes; do
  "$exe" generate "$mesh" -n 5 -o "$tmp/$mesh.vtu" >/dev/null || fail "generate $mesh"
  for bricks in 3 5; do
    "$exe" partition "$tmp/$mesh.vtu" --bricks $bricks -o "$tmp/${mesh}_$bricks" >/dev/null || fail "partition $mesh"
  done
  for view in ortho persp inside; do
    scene "$mesh" "${mesh}_$view" "${!view}"
    methods=("exact --interpolation canonical-tets" "pt-breakpoints --tetrahedralize all" "pt-linear")
    [ $view = inside ] && methods=("exact --interpolation canonical-tets")  # projection drops cells the eye is in
    for m in "${methods[@]}"; do
      tag="${mesh}_${view}_${m%% *}"
      "$exe" render "$tmp/${mesh}_$view.json" --method $m --npy "$tmp/$tag.npy" -o "$tmp/$tag.png" >/dev/null 2>&1 ||
        fail "render $tag"
      for P in $ranks; do
        bricks=$(( P % 2 ? 5 : 3 ))
        with_mesh "$tmp/${mesh}_$view.json" "${mesh}_$bricks" "$tmp/b.json"
        mpi $P render "$tmp/b.json" --method $m --threads 1 --npy "$tmp/d.npy" -o "$tmp/d.png" >/dev/null 2>"$tmp/err" ||
          { fail "mpirun -np $P $tag, $bricks bricks: $(cat "$tmp/err")"; continue; }
        if [ "${m%% *}" = pt-linear ]; then  # an approximation per cell: a cut cell's pieces differ from it
          [ $P = 1 ] && cp "$tmp/d.npy" "$tmp/p1_$bricks.npy"
          [ $P = 3 ] && same "$tmp/d.npy" "$tmp/p1_5.npy" 1e-6 "$tag: 3 ranks against 1, 5 bricks"
        else
          same "$tmp/d.npy" "$tmp/$tag.npy" 1e-6 "$tag: $P ranks, $bricks bricks against the whole mesh"
        fi
      done
    done
  done
  # The mesh itself under mpirun: cut in memory into one brick per rank.
  mpi 3 render "$tmp/${mesh}_persp.json" --method exact --interpolation canonical-tets --threads 1 \
    --npy "$tmp/m.npy" -o "$tmp/m.png" >/dev/null 2>&1 || fail "mpirun -np 3 $mesh in memory"
  same "$tmp/m.npy" "$tmp/${mesh}_persp_exact.npy" 1e-6 "$mesh cut in memory over 3 ranks"
  # Colour and extinction from two fields (here the one field twice): every cell is drawn over its
  # canonical tetrahedra, so bricks that cut cells leave no seam: 3 ranks give the whole mesh's picture.
  field=$("$py" -c "import json,sys; print(json.load(open(sys.argv[1]))['field'])" "$tmp/${mesh}_persp.json")
  "$exe" render "$tmp/${mesh}_persp.json" --opacity-field "$field" --threads 1 --npy "$tmp/two1.npy" \
    -o "$tmp/two1.png" >/dev/null 2>&1 || fail "$mesh with --opacity-field"
  mpi 3 render "$tmp/${mesh}_persp.json" --opacity-field "$field" --threads 1 --npy "$tmp/two3.npy" \
    -o "$tmp/two3.png" >/dev/null 2>&1 || fail "mpirun -np 3 $mesh with --opacity-field"
  same "$tmp/two3.npy" "$tmp/two1.npy" 1e-6 "$mesh, two fields over 3 ranks against 1 process"
done

m0=${meshes%% *}
# A turntable: each frame equals the single process's.
mpi 3 render "$tmp/${m0}_5" --method exact --interpolation canonical-tets --threads 1 --frames 3 --orbit 90 \
  --size 48x40 -o "$tmp/t_%d.png" --npy "$tmp/t_%d.npy" >/dev/null 2>&1 || fail "turntable over 3 ranks"
"$exe" render "$tmp/$m0.vtu" --method exact --interpolation canonical-tets --frames 3 --orbit 90 --size 48x40 \
  -o "$tmp/u_%d.png" --npy "$tmp/u_%d.npy" >/dev/null 2>&1 || fail "turntable in one process"
for f in 0 2; do same "$tmp/t_$f.npy" "$tmp/u_$f.npy" 1e-6 "turntable frame $f over 3 ranks"; done

# More ranks than bricks: the others idle.
mpi 4 render "$tmp/${m0}_3" --method exact --interpolation canonical-tets --threads 1 --npy "$tmp/i.npy" \
  -o "$tmp/i.png" --size 72x64 >/dev/null 2>&1 || fail "4 ranks, 3 bricks"
"$exe" render "$tmp/$m0.vtu" --method exact --interpolation canonical-tets --npy "$tmp/s.npy" -o "$tmp/s.png" \
  --size 72x64 >/dev/null 2>&1
same "$tmp/i.npy" "$tmp/s.npy" 1e-6 "4 ranks over 3 bricks"

# Cell data drawn constant over each cell (each cell its own points, seams between them), over 3 ranks.
"$exe" generate mixed -n 5 --cell-data -o "$tmp/cells.vtu" >/dev/null || fail "generate --cell-data"
mpi 3 render "$tmp/cells.vtu" --method exact --interpolation canonical-tets --threads 1 --npy "$tmp/c3.npy" \
  -o "$tmp/c3.png" --size 64x56 >/dev/null 2>&1 || fail "cell data over 3 ranks"
"$exe" render "$tmp/cells.vtu" --method exact --interpolation canonical-tets --npy "$tmp/c1.npy" -o "$tmp/c1.png" \
  --size 64x56 >/dev/null 2>&1
same "$tmp/c3.npy" "$tmp/c1.npy" 1e-6 "cell data over 3 ranks"

# A missing and a truncated brick: every rank exits non-zero, rank 0 names each failing rank and file.
cp -r "$tmp/mixed_5" "$tmp/bad"
rm "$tmp/bad/brick_0001.vtu"
head -c 300 "$tmp/mixed_5/brick_0004.vtu" > "$tmp/bad/brick_0004.vtu"
mpi 3 render "$tmp/bad" --threads 1 -o "$tmp/bad.png" >/dev/null 2>"$tmp/err"; code=$?
if [ $code -eq 0 ] || [ $code -eq 124 ] || ! grep -q "rank [0-9]: .*brick_0001.vtu: no such file" "$tmp/err" ||
   ! grep -q "rank [0-9]: .*brick_0004.vtu: truncated" "$tmp/err" || [ -e "$tmp/bad.png" ]; then
  fail "bad bricks: exit $code: $(cat "$tmp/err")"
else passed=$((passed+1)); fi
echo '{"cellproj_partition": 1, "source": "x", "cells": 1, "fields": [], "bricks": [], "tree": []}' > "$tmp/bad/partition.json"
"$exe" render "$tmp/bad" -o "$tmp/bad.png" >/dev/null 2>"$tmp/err"; code=$?
[ $code -eq 1 ] && grep -q "partition.json: the index lists no bricks" "$tmp/err" && passed=$((passed+1)) ||
  fail "empty index: exit $code: $(cat "$tmp/err")"

echo "mpi_render: $passed passed, $failed failed"
[ $failed -eq 0 ]
