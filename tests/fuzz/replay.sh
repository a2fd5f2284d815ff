#!/usr/bin/env bash
# Replays fuzzer inputs through the command line, which must refuse each one cleanly: exit 0 or 1,
# no "internal error", no crash, within 5 minutes. Used by bench/fuzz.sh on what it found and by
# ctest on tests/fuzz/regressions/ (every input the fuzzers ever crashed on).
#   replay.sh CELLPROJ HARNESS FILE...     (HARNESS: vtu vtk exodus cgns plot3d tetgen off points scene)
set -u
exe=$1 name=$2; shift 2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
case $name in vtu) ext=.vtu;; vtk) ext=.vtk;; exodus) ext=.exo;; cgns) ext=.cgns;; plot3d) ext=.xyz;;
              tetgen) ext=.node;; off) ext=.off;; points) ext=.xyzs;; scene) ext=.json;;
              *) echo "unknown harness $name"; exit 2;; esac
"$exe" generate box-tets -n 2 -o "$tmp/box.vtu" >/dev/null  # the mesh the scene seeds name
findings=0
for file in "$@"; do
  in=$tmp/input$ext
  if [ "$name" = tetgen ]; then  # the harness's input: .node, a NUL byte, .ele
    python3 -c "import sys; a,_,b=open(sys.argv[1],'rb').read().partition(b'\0'); open(sys.argv[2],'wb').write(a); open(sys.argv[3],'wb').write(b)" \
      "$file" "$in" "${in%.node}.ele"
  else cp "$file" "$in"; fi
  if [ "$name" = scene ]; then
    out=$(timeout 300 "$exe" render "$in" --size 16x16 -o "$tmp/x.png" --max-memory 2 2>&1); rc=$?
  else
    out=$(timeout 300 "$exe" info "$in" --max-memory 2 2>&1); rc=$?
  fi
  if [ $rc -gt 1 ] || grep -q "internal error" <<<"$out"; then
    echo "FINDING $name $(basename "$file"): exit $rc: $(tail -c 400 <<<"$out")"; findings=$((findings + 1))
  fi
done
[ $findings -eq 0 ]
