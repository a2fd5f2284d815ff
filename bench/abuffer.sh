#!/usr/bin/env bash
# Issue 3's A-buffer target: mpvo-abuffer against mpvo on every non-convex dataset of ../shared/data
# at 1024^2, 8 views, orthographic and perspective, every order checked by the oracle. mpvo-abuffer
# finds its gap relations from the faces' overlaps (--gaps auto, the default) and asks the A-buffer
# only for views that need it; the A-buffer alone (--gaps abuffer) and its reference that orders
# every pixel's list (--abuffer-every-pixel) are timed next to it. The timed runs and the oracle's
# check are separate sortbench runs.
# usage: bash bench/abuffer.sh [BUILD_DIR] [OUT_DIR]     (about 2 minutes on 2 cores)
set -euo pipefail
build=${1:-build}; out=${2:-bench/results}
exe=$build/bin/cellproj
source "$(dirname "$0")/shared_data.sh"
mkdir -p "$out"
mapfile -t meshes < <(shared_meshes --non-convex)
[ ${#meshes[@]} -gt 0 ] || { echo "no datasets under $shared_data" >&2; exit 1; }
rows=$out/abuffer_1024.jsonl
run() { "$exe" sortbench "${meshes[@]}" --views 8 --size 1024x1024 --projection both "$@" --json; }
# Timed without the oracle (it would evict the caches between two timed sorts), checked apart.
run --sorts mpvo,mpvo-abuffer > "$rows"
run --sorts mpvo-abuffer --gaps abuffer >> "$rows"
run --sorts mpvo-abuffer --abuffer-every-pixel >> "$rows"
run --sorts mpvo-abuffer --check | sed 's/"sort":"mpvo-abuffer"/"sort":"mpvo-abuffer-checked"/' >> "$rows"
python3 - "$rows" <<'EOF'
import json, os, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
key = lambda r: (os.path.basename(r["mesh"]), r["projection"])
pick = lambda sort, gaps, every=False: {key(r): r for r in rows if r["sort"] == sort and r["gaps"] == gaps
                                        and r["abuffer_every_pixel"] == every}
mpvo, auto, alone = pick("mpvo", "auto"), pick("mpvo-abuffer", "auto"), pick("mpvo-abuffer", "abuffer")
every, checked = pick("mpvo-abuffer", "auto", True), pick("mpvo-abuffer-checked", "auto")
ms = lambda s: f"{s * 1e3:.3f}"
gaps_ms = lambda r: r["phase_seconds"].get("overlaps", 0) + r["phase_seconds"].get("abuffer", 0)
print("| mesh | cells | proj | mpvo ms | mpvo-abuffer ms | ratio (target <= 3) | gaps ms | face pairs tested | "
      "views on the A-buffer | violations (pixels) | cycles | A-buffer alone: ms | ratio | A-buffer ms | runs | "
      "every pixel: A-buffer ms | sweep gain | split ms |")
print("| --- | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
for k, s in auto.items():
    m, a, e, c = mpvo[k], alone[k], every[k], checked[k]
    ab, ae = a["phase_seconds"]["abuffer"], e["phase_seconds"]["abuffer"]
    print(f"| {k[0]} | {s['cells']} | {k[1]} | {ms(m['median_seconds'])} | {ms(s['median_seconds'])} | "
          f"{s['median_seconds'] / m['median_seconds']:.2f} | {ms(gaps_ms(s))} | {s['gap_pair_tests']} | "
          f"{s['abuffer_views']} of {s['views']} | {c['violations']} ({c['violating_pixels']}) | {s['cycles']} | "
          f"{ms(a['median_seconds'])} | {a['median_seconds'] / m['median_seconds']:.2f} | {ms(ab)} | {a['abuffer_runs']} | "
          f"{ms(ae)} | {ae / ab:.2f} | {s['split_seconds'] * 1e3:.1f} |")
EOF
