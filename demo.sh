#!/usr/bin/env bash
# Quick start (1): install what is missing, build, and render the built-in default scene.
set -euo pipefail
cd "$(dirname "$0")"
t0=$(date +%s%N)
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
t1=$(date +%s%N)
./build/bin/cellproj render scenes/default.json -o out/default.png
t2=$(date +%s%N)
ms() { printf '%d.%02d s' $(($1 / 1000000000)) $(($1 % 1000000000 / 10000000)); }
echo "out/default.png rendered in $(ms $((t2 - t1))) (set-up and build: $(ms $((t1 - t0))))"
