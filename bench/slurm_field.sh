#!/usr/bin/env bash
# A field of wells as a Slurm array (examples/cluster) against `caliper3d batch -j 1` and
# `-j 2` on the same field and machine: wells per second and peak memory. The cluster is the
# one-node Slurm of the tests (tests/cluster/local_slurm.sh, CPUs = this machine's cores),
# timed from the submission to the merged summary; each ROWS_PER_TASK value is one run.
# Figures go to docs/benchmarks.md ("A field on Slurm").
#   bench/slurm_field.sh [BUILD_DIR] [WELLS] [LENGTH_M] [STEP_M] [VERB] ["ROWS_PER_TASK..."]
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build/release}
wells=${2:-100}
length=${3:-1000}
step=${4:-0.05}
verb=${5:-report}
per_task_runs=${6:-"1 10 50"}
bin="$(cd "$build" && pwd)/app/caliper3d"
cpus=$(nproc)
# shellcheck source-path=SCRIPTDIR source=../tests/cluster/local_slurm.sh
source "$src/tests/cluster/local_slurm.sh"
work=$(mktemp -d /tmp/caliper3d-slurm-bench.XXXXXX)
trap 'local_slurm_stop; rm -rf "$work"' EXIT

echo "machine: $cpus cores, $(free -g | awk '/^Mem:/ {print $2}') GiB, $(uptime | sed 's/.*load/load/')"
"$bin" synth --field "$wells" --length "$length" --step "$step" -o "$work/field/" >/dev/null
sed -i "s/,report,/,$verb,/" "$work/field/manifest.csv"
echo "field: $wells wells of $length m every $step m ($(du -sm "$work/field" | cut -f1) MB), verb $verb"

now() { date +%s.%N; }
# Wells per second, the time, and the ratio to batch -j 2 once that is known.
rate() {
  awk -v l="$1" -v w="$wells" -v s="$2" -v e="$3" -v ref="${ref_s:-0}" 'BEGIN {
    t = e - s; printf "%s: %.2f s, %.2f wells/s", l, t, w / t
    if (ref > 0) printf ", %.2f x the time of batch -j 2", t / ref
    printf "\n" }'
}
# The median and largest peak RSS of the wells' processes, from the summary lines.
perWell() {
  grep -o '"peak_rss_mb":[0-9.]*' "$1" | cut -d: -f2 | sort -n |
    awk '{ v[NR] = $1 } END { printf "  per well: peak RSS median %.0f MB, max %.0f MB (%d ok of %d)\n",
      v[int((NR + 1) / 2)], v[NR], ok, NR }' ok="$(grep -c '"status":"ok"' "$1")"
}

for jobs in 1 2; do
  cd "$work" && rm -rf out
  start=$(now)
  /usr/bin/time -f "%M" -o "$work/rss" "$bin" batch "$work/field/manifest.csv" -j "$jobs" \
    -o out/ --summary "$work/summary-j$jobs.jsonl" >/dev/null
  end=$(now)
  rate "batch -j $jobs" "$start" "$end"
  echo "  batch process itself: peak RSS $(($(cat "$work/rss") / 1024)) MB"
  perWell "$work/summary-j$jobs.jsonl"
  [ "$jobs" = 2 ] && ref_s=$(awk -v s="$start" -v e="$end" 'BEGIN { print e - s }')
done

local_slurm_start "$work/slurm" "$cpus" || { echo "the local Slurm did not start" >&2; exit 1; }
export CALIPER3D="$bin"
for per_task in $per_task_runs; do
  run="$work/run-$per_task"
  mkdir -p "$run" && cd "$run"
  start=$(now)
  ROWS_PER_TASK=$per_task "$src/examples/cluster/submit-field.sh" "$work/field/manifest.csv" \
    -o out/ >/dev/null
  local_slurm_wait_idle 900
  end=$(now)
  rate "Slurm array, ROWS_PER_TASK=$per_task ($(((wells + per_task - 1) / per_task)) tasks)" "$start" "$end"
  tail -n 2 logs/field-merge-*.out | sed 's/^/  merge: /'
  perWell field-summary.jsonl
done

# What the daemons themselves hold (high-water mark of resident memory).
for d in slurmctld slurmd munge/munged; do
  pid=$(cat "$local_slurm_dir/$d.pid")
  echo "$(basename $d): peak RSS $(awk '/^VmHWM/ {printf "%.0f MB", $2 / 1024}' "/proc/$pid/status")"
done
