#!/usr/bin/env bash
# Issue 3's A-buffer target: mpvo-abuffer against mpvo on every non-convex dataset of ../shared/data
# at 1024^2, 8 views, orthographic and perspective, every order checked by the oracle; and the
# A-buffer's sweep against ordering every pixel's list (--abuffer-every-pixel). The timed runs
# and the oracle's check are separate sortbench runs.
# usage: bash bench/abuffer.sh [BUILD_DIR] [OUT_DIR]     (about 4 minutes on 2 cores)
set -euo pipefail
build=${1:-build}; out=${2:-bench/results}
exe=$build/bin/cellproj
source "$(dirname "$0")/shared_data.sh"
mkdir -p "$out"
mapfile -t meshes < <(shared_meshes --non-convex)
[ ${#meshes[@]} -gt 0 ] || { echo "no datasets under $shared_data" >&2; exit 1; }
rows=$out/abuffer_1024.jsonl
# Timed without the oracle (it would evict the caches between two timed sorts), checked apart.
"$exe" sortbench "${meshes[@]}" --views 8 --size 1024x1024 --projection both --sorts mpvo,mpvo-abuffer --json > "$rows"
"$exe" sortbench "${meshes[@]}" --views 8 --size 1024x1024 --projection both --sorts mpvo-abuffer --abuffer-every-pixel \
  --json >> "$rows"
"$exe" sortbench "${meshes[@]}" --views 8 --size 1024x1024 --projection both --sorts mpvo-abuffer --check --json \
  | sed 's/"sort":"mpvo-abuffer"/"sort":"mpvo-abuffer-checked"/' >> "$rows"
python3 - "$rows" <<'EOF'
import json, os, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
key = lambda r: (os.path.basename(r["mesh"]), r["projection"])
mpvo = {key(r): r for r in rows if r["sort"] == "mpvo"}
sweep = {key(r): r for r in rows if r["sort"] == "mpvo-abuffer" and not r["abuffer_every_pixel"]}
every = {key(r): r for r in rows if r["sort"] == "mpvo-abuffer" and r["abuffer_every_pixel"]}
checked = {key(r): r for r in rows if r["sort"] == "mpvo-abuffer-checked"}
print("| mesh | cells | proj | mpvo ms | mpvo-abuffer ms | ratio (target <= 3) | A-buffer ms | runs | pixels | "
      "violations (pixels) | cycles | every pixel: A-buffer ms | sweep gain | split ms |")
print("| --- | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
for k, s in sweep.items():
    m, e, c = mpvo[k], every[k], checked[k]
    a, ae = s["phase_seconds"]["abuffer"], e["phase_seconds"]["abuffer"]
    print(f"| {k[0]} | {s['cells']} | {k[1]} | {m['median_seconds']*1e3:.3f} | {s['median_seconds']*1e3:.3f} | "
          f"{s['median_seconds']/m['median_seconds']:.2f} | {a*1e3:.3f} | {s['abuffer_runs']} | {s['abuffer_fragments']} | "
          f"{c['violations']} ({c['violating_pixels']}) | {s['cycles']} | {ae*1e3:.3f} | {ae/a:.2f} | "
          f"{s['split_seconds']*1e3:.1f} |")
EOF
