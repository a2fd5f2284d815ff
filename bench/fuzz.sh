#!/usr/bin/env bash
# Fuzzes every mesh reader and the scene files with libFuzzer (clang, AddressSanitizer and
# UndefinedBehaviorSanitizer) for SECONDS in all, then replays every crash input through the
# command line. The harnesses read in-process, so a third-party reader's crash is seen (and its
# coverage guides the search); the command line reads in an isolated process, so such a crash
# must come back as an error naming the file ("contained"). A finding is an input on which the
# command line itself crashes, hangs, or says "internal error"; bench/fuzz.sh exits 1 on one.
# Crash inputs land in build-fuzz/crashes/NAME/; a finding becomes a regression input under
# tests/fuzz/regressions/NAME/ once fixed.
#   bench/fuzz.sh SECONDS [HARNESS...]      (default: all; docs/reliability.md has a 3600 s run)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:?usage: bench/fuzz.sh SECONDS [HARNESS...]}; shift
harnesses=(${@:-vtu vtk exodus cgns plot3d tetgen off points scene})
dir=build-fuzz
bash scripts/setup.sh --fuzz
CC=clang CXX=clang++ cmake -S . -B $dir -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCELLPROJ_FUZZ=ON -DCELLPROJ_BUILD_TESTS=OFF >/dev/null
cmake --build $dir --target fuzzers -j"$(nproc)" >/dev/null
rm -rf $dir/seeds && $dir/bin/fuzz_seeds $dir/seeds >/dev/null
per=$(( seconds / ${#harnesses[@]} )); [ $per -ge 1 ] || per=1
# allocator_may_return_null: the readers meet absurd sizes in garbled headers and must refuse them,
# as they would with the real allocator; leaks are VTK's caches, not findings. One allocation is
# capped at 512 MiB (the harnesses' --max-memory is 128 MiB): ASan zero-fills and poisons what it
# hands out, so a garbled header that has a library calloc gigabytes costs seconds per execution.
export ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1:max_allocation_size_mb=512 UBSAN_OPTIONS=print_stacktrace=1
# Each fuzzing process writes its inputs to a folder of its own under TMPDIR: this run's, removed
# at the end (forked jobs killed by a crash or a timeout leave theirs behind).
TMPDIR=$(mktemp -d "${TMPDIR:-/tmp}/cellproj-fuzz-run-XXXXXX"); export TMPDIR
trap 'rm -rf "$TMPDIR"' EXIT
printf '%-8s %12s %8s %8s %8s %9s %9s\n' harness executions exec/s corpus cov crashes findings
findings=0; : >$dir/findings.txt
for h in "${harnesses[@]}"; do
  corpus=$dir/corpus/$h crashes=$dir/crashes/$h
  mkdir -p "$corpus" "$crashes"
  cp -n $dir/seeds/$h/* "$corpus"/ 2>/dev/null || true
  [ -d tests/fuzz/regressions/$h ] && cp -n tests/fuzz/regressions/$h/* "$corpus"/ 2>/dev/null || true
  set +e
  $dir/bin/fuzz_$h "$corpus" -fork="$(nproc)" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -max_total_time=$per -timeout=30 -rss_limit_mb=2048 -malloc_limit_mb=1024 -max_len=65536 \
    -artifact_prefix="$crashes/" >"$dir/log_$h.txt" 2>&1
  set -e
  last=$(grep -E '^#[0-9]+: cov:' "$dir/log_$h.txt" | tail -1 || true)
  execs=$(sed -E 's/^#([0-9]+):.*/\1/' <<<"$last"); cov=$(sed -nE 's/.*cov: ([0-9]+).*/\1/p' <<<"$last")
  rate=$(( ${execs:-0} / per ))
  n=$(ls "$crashes" | wc -l) f=0
  if [ "$n" -gt 0 ]; then
    tests/fuzz/replay.sh $dir/bin/cellproj "$h" "$crashes"/* >>"$dir/findings.txt" || true
    f=$(grep -c "^FINDING $h " "$dir/findings.txt" || true)
  fi
  findings=$((findings + f))
  printf '%-8s %12s %8s %8s %8s %9s %9s\n' "$h" "${execs:-?}" "${rate:-?}" "$(ls "$corpus" | wc -l)" "${cov:-?}" "$n" "$f"
done
[ $findings -eq 0 ] || { echo "findings:"; cat $dir/findings.txt; exit 1; }
echo "crashes of the in-process readers, all contained by the command line's isolated reader: see $dir/crashes/"
