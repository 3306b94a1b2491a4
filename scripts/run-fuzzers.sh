#!/usr/bin/env bash
# Builds the io libFuzzer targets with clang (AddressSanitizer + UBSan, any
# UB report fatal) in build/fuzz and runs each for SECONDS (default 60), two
# at a time, from its seed corpus: tests/fuzz/corpus/<kind>, plus the shared
# LAS edge cases when ../shared/data is present (copied into the build
# folder, never into the repository). Fails when any target crashes, hangs
# (one input over 10 s) or runs out of memory; the input that did it is left
# in build/fuzz/crashes/ and the end of the target's log is printed.
#   scripts/run-fuzzers.sh [SECONDS]
set -euo pipefail
seconds=${1:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build/fuzz"
targets=(fuzz_las_reader fuzz_las_header fuzz_column_text fuzz_survey_reader fuzz_batch_manifest fuzz_dlis_reader)

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined" \
  -DCALIPER3D_GUI=OFF -DCALIPER3D_BENCH=OFF -DCALIPER3D_TESTS=ON -DCALIPER3D_FUZZ=ON >/dev/null
cmake --build "$build" -j2 --target "${targets[@]}"

mkdir -p "$build/crashes" "$build/logs"
for kind in las text survey manifest dlis; do
  mkdir -p "$build/corpus/$kind"
  if [ -d "$root/tests/fuzz/corpus/$kind" ]; then cp "$root"/tests/fuzz/corpus/$kind/* "$build/corpus/$kind/"; fi
done
shared="$root/../shared/data"
if [ -d "$shared/las_edge_cases" ]; then
  cp "$shared"/las_edge_cases/*.las "$build/corpus/las/"
fi
if [ -d "$shared/dlis" ]; then
  # dlisio's small synthetic files (the envelope, sets, every representation code, frames).
  find "$shared/dlis" -name '*.dlis' -size -64k -exec cp {} "$build/corpus/dlis/" \;
fi
if [ -d "$shared/surveys" ]; then
  cp "$shared"/surveys/*.csv "$shared"/surveys/*.txt "$build/corpus/survey/" 2>/dev/null || true
fi
chmod -R u+w "$build/corpus"

corpusOf() {
  case $1 in
    fuzz_column_text) echo "$build/corpus/text" ;;
    fuzz_survey_reader) echo "$build/corpus/survey" ;;
    fuzz_batch_manifest) echo "$build/corpus/manifest" ;;
    fuzz_dlis_reader) echo "$build/corpus/dlis" ;;
    *) echo "$build/corpus/las" ;;
  esac
}

runOne() {
  local target=$1 log="$build/logs/$1.log"
  if "$build/tests/fuzz/$target" -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=2048 -timeout=10 \
      -print_final_stats=1 -artifact_prefix="$build/crashes/$target-" "$(corpusOf "$target")" >"$log" 2>&1; then
    echo "== $target: no crash in ${seconds}s ($(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$') runs)"
  else
    echo "== $target: FAILED (input in $build/crashes/, log $log)"
    tail -n 40 "$log"
    return 1
  fi
}

status=0
pids=()
for target in "${targets[@]}"; do
  runOne "$target" &
  pids+=($!)
  if [ ${#pids[@]} -eq 2 ]; then
    wait "${pids[0]}" || status=1
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
exit $status
