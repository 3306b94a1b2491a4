#!/usr/bin/env bash
# Timed command-line run: synthesise a well and export it as .iv, printing
# wall time and peak memory of each step (GNU time). Figures go to docs/benchmarks.md.
#   bench/export_cli.sh [BUILD_DIR] [LENGTH_M] [STEP_M]
set -euo pipefail
build=${1:-build/release}
length=${2:-500}
step=${3:-0.0025}
bin="$build/app/caliper3d"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/time -f "synth: %e s, peak RSS %M KiB" "$bin" synth -o "$work/well.txt" --length "$length" --step "$step"
ls -l "$work/well.txt" | awk '{printf "log: %.1f MB\n", $5/1e6}'
for mode in "--ascii" "" "--gzip"; do
  # shellcheck disable=SC2086
  /usr/bin/time -f "export ${mode:-binary}: %e s, peak RSS %M KiB" \
    "$bin" export "$work/well.txt" -o "$work/well.iv" --bit-size 8.5in $mode 2>&1 | grep -v glxglue
  ls -l "$work/well.iv" | awk '{printf "  .iv size: %.1f MB\n", $5/1e6}'
  rm -f "$work/well.iv"
done
