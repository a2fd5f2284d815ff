#!/usr/bin/env bash
# Distributed rendering (issue 18, docs/parallel.md), measured in one run on this machine:
#  1. partitioning the 1M-tetrahedra box: seconds and peak memory against reading the mesh alone;
#  2. strong scaling, 1 to 4 ranks of one thread each, pt-linear at 1024^2, against the single
#     process on the whole mesh (1 and 2 threads): this machine has 2 cores, so 2 ranks is the ceiling;
#  3. compositing: binary swap's seconds and bytes per rank against image size and P;
#  4. load balance: max/mean render time over 4 ranks for the cost model (projected) against a
#     plain cell count split, on the 1M box and on Blunt Fin's 187k graded tetrahedra (../shared/data).
#  5. each method over 5 bricks against one process on the whole mesh (docs/parallel.md).
# usage: bench/mpi.sh [BUILD_DIR]   (about 4 minutes; prints tables, saved in bench/results/mpi.txt)
set -euo pipefail
build=${1:-build}
exe=$(realpath "$build/bin/cellproj")
py=${PYTHON:-python3}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl=self,vader
stats() { tail -1 "$work/err"; }
mpi() { local p=$1; shift; mpirun --oversubscribe -np "$p" "$exe" "$@"; }

# The 1M-tetrahedra box and its scene (bench/scenes/box_1m.json, shared with the other benchmarks).
"$exe" generate box-tets -n 55 -o "$work/box_1m.vtu" >/dev/null
cp "$(dirname "$0")/scenes/box_1m.json" "$work/box.json"
with_mesh() { sed "s#\"mesh\": \"[^\"]*\"#\"mesh\": \"$2\"#" "$1" > "$3"; }

echo "== 1. partition (1M tetrahedra)"
"$exe" info "$work/box_1m.vtu" --json > "$work/info.json"
for n in 4 16; do
  "$exe" partition "$work/box_1m.vtu" --bricks $n -o "$work/box_$n" --stats >/dev/null 2>"$work/err"
  stats
done
"$exe" partition "$work/box_1m.vtu" --bricks 4 --cost cells -o "$work/box_cells" >/dev/null

echo "== 2. strong scaling: pt-linear 1024^2 (one thread per rank)"
for t in 1 2; do
  "$exe" render "$work/box.json" --method pt-linear --threads $t -o "$work/whole.png" --npy "$work/whole.npy" \
    --stats 2>"$work/err" >/dev/null
  echo "{\"whole_mesh\": true, \"threads\": $t, $(stats | $py -c 'import json,sys; j=json.load(sys.stdin); print("\"frame_seconds\": %.3f, \"load_seconds\": %.3f}" % (j["frame_seconds"], j["load_seconds"]))')"
done
with_mesh "$work/box.json" box_4 "$work/b4.json"
for P in 1 2 3 4; do
  mpi $P render "$work/b4.json" --method pt-linear --threads 1 -o "$work/d.png" --npy "$work/d$P.npy" --stats \
    2>"$work/err" >/dev/null
  stats > "$work/scaling_$P.json"
done
$py - "$work" <<'EOF'
import json, sys
w = sys.argv[1]
print("| ranks | frame s (render of the slowest + composite) | render s per rank | composite s (max) | MB sent (max rank) | imbalance |")
print("|---:|---:|---|---:|---:|---:|")
for P in (1, 2, 3, 4):
    j = json.load(open(f"{w}/scaling_{P}.json"))
    r = j["per_rank"]
    frame = max(x["render_seconds"] + x["wait_seconds"] + x["composite_seconds"] for x in r)
    print(f"| {P} | {frame:.3f} | {' '.join('%.2f' % x['render_seconds'] for x in r)} | "
          f"{max(x['composite_seconds'] for x in r):.4f} | {max(x['bytes_sent'] for x in r) / 1e6:.2f} | {j['imbalance']:.2f} |")
EOF
for P in 2 3 4; do "$exe" compare "$work/d1.npy" "$work/d$P.npy"; echo "  (P=$P against P=1)"; done

echo "== 3. compositing against image size (4 ranks, pt-linear)"
echo "| size | P | composite s (max rank) | KB sent (max rank) | KB received (rank 0) |"
echo "|---:|---:|---:|---:|---:|"
for size in 256 512 1024 2048; do
  for P in 2 4; do
    mpi $P render "$work/b4.json" --method pt-linear --threads 1 --size ${size}x$size -o "$work/c.png" --stats \
      2>"$work/err" >/dev/null
    stats | $py -c "import json,sys; j=json.load(sys.stdin); r=j['per_rank']
print('| %d | %d | %.4f | %.0f | %.0f |' % ($size, $P, max(x['composite_seconds'] for x in r), max(x['bytes_sent'] for x in r)/1e3, r[0]['bytes_received']/1e3))"
  done
done

echo "== 4. load balance over 4 ranks: max/mean render seconds"
fin=$(dirname "$0")/../../shared/data/nasa_bluntfin/bluntfin_tets.vtu
echo "| mesh | cost model | imbalance (CPU s, max/mean) | slowest rank CPU s |"
echo "|---|---|---:|---:|"
for cost in projected cells; do
  with_mesh "$work/box.json" "$([ $cost = projected ] && echo box_4 || echo box_cells)" "$work/lb.json"
  mpi 4 render "$work/lb.json" --method pt-linear --threads 1 -o "$work/lb.png" --stats 2>"$work/err" >/dev/null
  stats | $py -c "import json,sys; j=json.load(sys.stdin)
print('| box 1M | $cost | %.2f | %.3f |' % (j['imbalance'], max(x['render_cpu_seconds'] for x in j['per_rank'])))"
done
if [ -f "$fin" ]; then
  for cost in projected cells; do
    "$exe" partition "$fin" --bricks 4 --cost $cost -o "$work/fin_$cost" >/dev/null 2>&1
    mpi 4 render "$work/fin_$cost" --field Density --method pt-linear --threads 1 --size 1024x1024 -o "$work/fin.png" --stats \
      2>"$work/err" >/dev/null
    stats | $py -c "import json,sys; j=json.load(sys.stdin)
print('| Blunt Fin tets | $cost | %.2f | %.3f |' % (j['imbalance'], max(x['render_cpu_seconds'] for x in j['per_rank'])))"
  done
else
  echo "(../shared/data missing: Blunt Fin skipped)"
fi

echo "== 5. each method over 5 bricks and 2 ranks against one process on the whole mesh (256^2, max abs / rms)"
echo "| mesh | method | max abs | rms |"
echo "|---|---|---:|---:|"
for mesh in swirl mixed graded-tets; do
  "$exe" generate $mesh -n 8 -o "$work/$mesh.vtu" >/dev/null
  "$exe" partition "$work/$mesh.vtu" --bricks 5 -o "$work/${mesh}_5" >/dev/null
  for m in "exact" "exact --interpolation canonical-tets" "pt-breakpoints" "pt-breakpoints --tetrahedralize all" \
           "pt-analytic" "pt-table" "pt-linear" "slicing" "exact --interpolation canonical-tets --iso 0.5:1,0,0,0.6"; do
    "$exe" render "$work/$mesh.vtu" --method $m --size 256x256 --npy "$work/w.npy" -o "$work/w.png" >/dev/null 2>&1
    mpi 2 render "$work/${mesh}_5" --method $m --size 256x256 --threads 1 --npy "$work/b.npy" -o "$work/b.png" \
      >/dev/null 2>&1
    "$exe" compare "$work/w.npy" "$work/b.npy" | $py -c "import json, sys; j = json.load(sys.stdin)
print('| $mesh | $m | %.2g | %.2g |' % (j['max_abs'], j['rmse']))"
  done
done
