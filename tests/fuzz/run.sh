#!/bin/bash
# Runs the libFuzzer targets of build/fuzz for SECONDS each (default 30), seeded with scenes/, examples/models/, examples/rolling/ and the inputs that
# once found bugs (tests/fuzz/regressions/, replayed first: each must pass). A crash, a sanitizer report, a hang
# (over 5 s on one input) or memory over 2 GB fails the run and leaves the input in build/fuzz/findings/.
# Usage: tests/fuzz/run.sh [SECONDS]   (./test runs it briefly; a longer run: tests/fuzz/run.sh 3600)
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-30}
findings=build/fuzz/findings
export ROLLVIZ_COMPILE_MODELS=0 # model files found by the fuzzers run interpreted (no compiler per input)
mkdir -p "$findings"
for target in scene override sweep model; do
  exe=build/fuzz/tests/fuzz/fuzz_$target
  corpus=build/fuzz/corpus-$target
  mkdir -p "$corpus"
  regressions=tests/fuzz/regressions/$target
  if [ -d "$regressions" ] && [ -n "$(ls -A "$regressions")" ]; then
    echo "== fuzz_$target: replaying $(ls "$regressions" | wc -l) inputs that once found bugs"
    "$exe" -runs=0 -timeout=5 "$regressions"/*
  fi
  seeds=(tests/fuzz/seeds/$target)
  [ "$target" = scene ] && seeds=(scenes)
  [ "$target" = model ] && seeds=(examples/models examples/rolling)
  echo "== fuzz_$target: ${seconds} s"
  "$exe" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
    -artifact_prefix="$findings/$target-" "$corpus" "${seeds[@]}"
done
