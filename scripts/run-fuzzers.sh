#!/bin/sh
# Builds the io libFuzzer targets with clang in build/fuzz and runs each for
# SECONDS (default 60). Seeds: tests/fuzz/corpus, plus the shared LAS edge
# cases when ../shared/data is present (copied into the build folder, never
# into the repository). A crash leaves its input in build/fuzz/crashes/.
set -eu
seconds=${1:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build/fuzz"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined" \
  -DCALIPER3D_GUI=OFF -DCALIPER3D_BENCH=OFF -DCALIPER3D_FUZZ=ON >/dev/null
cmake --build "$build" -j2 --target fuzz_las_reader fuzz_column_text fuzz_las_header
mkdir -p "$build/corpus/las" "$build/corpus/text" "$build/crashes"
cp "$root"/tests/fuzz/corpus/las/* "$build/corpus/las/"
cp "$root"/tests/fuzz/corpus/text/* "$build/corpus/text/"
shared="$root/../shared/data"
if [ -d "$shared/las_edge_cases" ]; then
  for f in "$shared"/las_edge_cases/*.las; do cp "$f" "$build/corpus/las/"; done
  chmod u+w "$build"/corpus/las/*
fi
status=0
for target in fuzz_las_reader fuzz_las_header fuzz_column_text; do
  case $target in fuzz_column_text) corpus="$build/corpus/text" ;; *) corpus="$build/corpus/las" ;; esac
  echo "== $target for ${seconds}s"
  "$build/tests/fuzz/$target" -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=2048 -timeout=10 \
    -artifact_prefix="$build/crashes/$target-" "$corpus" || status=1
done
exit $status
