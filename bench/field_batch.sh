#!/usr/bin/env bash
# A field of wells through 'caliper3d batch': wells per second and peak memory at -j 1 and
# -j 2, and the cost of a well's own process (start, and a GL context for render) measured
# apart. Figures go to docs/benchmarks.md ("A field of wells").
#   bench/field_batch.sh [BUILD_DIR] [WELLS] [LENGTH_M] [STEP_M] [VERB]
set -euo pipefail
build=${1:-build/release}
wells=${2:-100}
length=${3:-1000}
step=${4:-0.05}
verb=${5:-report}
bin="$(cd "$build" && pwd)/app/caliper3d"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "machine: $(nproc) cores, $(uptime | sed 's/.*load/load/')"
/usr/bin/time -f "synth --field $wells: %e s" "$bin" synth --field "$wells" --length "$length" \
  --step "$step" -o "$work/field/" >/dev/null
du -sm "$work/field" | awk '{printf "field: %s MB of LAS\n", $1}'
sed -i "s/,report,/,$verb,/" "$work/field/manifest.csv"

# Per-well figures from the summary lines: the median and largest seconds and peak RSS.
perWell() {
  python3 - "$1" <<'PY'
import json, statistics, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
ok = [l for l in lines if l["status"] == "ok"]
s = sorted(l["seconds"] for l in ok); m = sorted(l["peak_rss_mb"] for l in ok)
print(f"  {len(ok)}/{len(lines)} ok; per well: median {statistics.median(s):.3f} s, "
      f"max {s[-1]:.3f} s, sum {sum(s):.1f} s; peak RSS median {statistics.median(m):.0f} MB, "
      f"max {m[-1]:.0f} MB")
PY
}

for jobs in 1 2; do
  rm -rf "$work/out"
  start=$(date +%s.%N)
  /usr/bin/time -f "%M" -o "$work/rss" "$bin" batch "$work/field/manifest.csv" -j "$jobs" \
    -o "$work/out/" --summary "$work/summary-$jobs.jsonl" >/dev/null
  end=$(date +%s.%N)
  awk -v w="$wells" -v s="$start" -v e="$end" -v j="$jobs" -v r="$(cat "$work/rss")" \
    'BEGIN { printf "batch -j %d: %.2f s, %.2f wells/s, largest process %.0f MB\n", j, e - s, w / (e - s), r / 1024 }'
  perWell "$work/summary-$jobs.jsonl"
done

# What a well's own process costs, apart from its work: 20 runs each, the mean.
"$bin" synth -o "$work/tiny.las" --length 10 --step 0.05 >/dev/null
timed() {
  local label=$1
  shift
  local start end
  start=$(date +%s.%N)
  for _ in $(seq 20); do "$@" >/dev/null 2>&1; done
  end=$(date +%s.%N)
  awk -v l="$label" -v s="$start" -v e="$end" 'BEGIN { printf "%s: %.1f ms\n", l, (e - s) * 1000 / 20 }'
}
timed "process start (caliper3d --version)" "$bin" --version
timed "report of a 10 m well" "$bin" report "$work/tiny.las" -o "$work/tiny.csv"
timed "render of a 10 m well, 64x64 (GL context and scene)" "$bin" render "$work/tiny.las" \
  -o "$work/tiny.png" --width 64 --height 64
# The GL context and first frame of render: its first picture less its load, 5 runs.
for _ in $(seq 5); do
  "$bin" render "$work/tiny.las" -o "$work/tiny.png" --width 64 --height 64 --stats 2>/dev/null |
    sed -n 's/.*first_picture_ms=\([0-9]*\) load_ms=\([0-9]*\).*/\1 \2/p'
done | awk '{ gl += $1 - $2; n++ } END { printf "render: GL context and first frame (first_picture_ms - load_ms): %.0f ms\n", gl / n }'
printf 'file,verb\n' >"$work/tiny-manifest.csv"
for _ in $(seq 20); do printf 'tiny.las,report\n' >>"$work/tiny-manifest.csv"; done
start=$(date +%s.%N)
"$bin" batch "$work/tiny-manifest.csv" -o "$work/tiny-out/" >/dev/null
end=$(date +%s.%N)
awk -v s="$start" -v e="$end" 'BEGIN { printf "batch of 20 rows of the 10 m well, per row: %.1f ms\n", (e - s) * 1000 / 20 }'
