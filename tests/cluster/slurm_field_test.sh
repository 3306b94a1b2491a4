#!/usr/bin/env bash
# The field examples on a real Slurm: starts a one-node cluster on this machine
# (local_slurm.sh), submits a 20-well synthetic field with examples/cluster/submit-field.sh
# (the array job field.sbatch and its merge job), waits, and checks every well's outputs
# and the merged summary. Fails, with the daemons' logs, if the cluster does not come up.
#   tests/cluster/slurm_field_test.sh CALIPER3D SOURCE_DIR
# Takes about 20-40 s on a 2-core machine (the wells are short; most of it is Slurm's
# one-second scheduling cadence).
set -euo pipefail
caliper3d=$(realpath "${1:?usage: slurm_field_test.sh CALIPER3D SOURCE_DIR}")
src=$(realpath "${2:?usage: slurm_field_test.sh CALIPER3D SOURCE_DIR}")
wells=${FIELD_WELLS:-20}
limit_s=${FIELD_TIMEOUT_S:-150}

# shellcheck source=local_slurm.sh
source "$src/tests/cluster/local_slurm.sh"
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

work=$(mktemp -d /tmp/caliper3d-slurm-field.XXXXXX)
cleanup() {
  local_slurm_stop
  # Keep the folder of a failed run for a look; a passing run leaves nothing behind.
  if [ "${passed:-0}" = 1 ]; then rm -rf "$work"; else echo "left for inspection: $work" >&2; fi
}
trap cleanup EXIT
passed=0
t0=$SECONDS

# The field: short synthetic wells, profiles in turn, one manifest row each.
mkdir -p "$work/field/logs-in" "$work/field/out"
cd "$work/field"
profiles=(example circle ellipse washout undergauge keyseat offcentre build hold turn)
echo "file,verbs,survey,wellhead,bit_size,overrides,output" >field.csv
for ((i = 0; i < wells; i++)); do
  name=$(printf 'well-%03d' "$i")
  "$caliper3d" synth -o "logs-in/$name.las" --length 60 --step 0.05 \
    --profile "${profiles[i % ${#profiles[@]}]}" >/dev/null
  echo "logs-in/$name.las,report,,,8.5in,,out/$name.csv" >>field.csv
done

# The batch verb, or its stand-in while this build has none.
if "$caliper3d" help batch >/dev/null 2>&1; then
  export CALIPER3D="$caliper3d"
else
  echo "note: this caliper3d has no batch verb; using tests/cluster/batch_standin.sh" >&2
  export CALIPER3D_REAL="$caliper3d"
  export CALIPER3D="$src/tests/cluster/batch_standin.sh"
fi

local_slurm_start "$work/slurm" 2 || fail "the one-node Slurm cluster did not start (logs above)"
echo "cluster up after $((SECONDS - t0)) s"

t_submit=$SECONDS
submitted=$("$src/examples/cluster/submit-field.sh" field.csv) || fail "submit-field.sh: $submitted"
echo "$submitted"
if ! local_slurm_wait_idle "$limit_s"; then
  local_slurm_logs
  fail "the field did not finish within $limit_s s"
fi
echo "field ran in $((SECONDS - t_submit)) s"

# Every job as Slurm recorded it: the array's tasks and the merge, all COMPLETED.
jobcomp="$work/slurm/log/jobcomp.txt"
[ -f "$jobcomp" ] || fail "no job completion log"
completed=$(grep -c 'JobState=COMPLETED' "$jobcomp" || true)
if [ "$completed" -ne $((wells + 1)) ]; then
  grep -v 'JobState=COMPLETED' "$jobcomp" >&2 || true
  tail -n 20 logs/*.out >&2 || true
  fail "$completed of $((wells + 1)) jobs completed"
fi
tasks=$(grep -o 'ArrayTaskId=[0-9]*' "$jobcomp" | sort -t= -k2 -n | cut -d= -f2 | tr '\n' ' ')
[ "$tasks" = "$(seq -s ' ' 0 $((wells - 1))) " ] || fail "array indices run: $tasks"

# Each well's report: present, one header and a row per section.
for ((i = 0; i < wells; i++)); do
  out=$(printf 'out/well-%03d.csv' "$i")
  [ -s "$out" ] || fail "no $out"
  [ "$(wc -l <"$out")" -gt 100 ] || fail "$out has $(wc -l <"$out") lines"
  head -n 1 "$out" | grep -q '^md_m,' || fail "$out does not start with the report header"
done

# The merged summary: one line per row, in manifest order, each ok and naming its file.
merged=field-summary.jsonl
[ -f "$merged" ] || fail "no merged summary $merged"
[ "$(wc -l <"$merged")" -eq "$wells" ] || fail "$merged has $(wc -l <"$merged") lines, not $wells"
row=0
while IFS= read -r line; do
  file=$(printf 'logs-in/well-%03d.las' "$row")
  [[ $line == *"\"$file\""* ]] || fail "summary line $row does not name $file: $line"
  [[ $line =~ \"status\":\ *\"ok\" ]] || fail "summary line $row is not ok: $line"
  row=$((row + 1))
done <"$merged"
grep -q "$wells of $wells wells, 0 not ok, 0 with no summary" logs/field-merge-*.out ||
  fail "merge job said: $(cat logs/field-merge-*.out)"

passed=1
echo "PASS: $wells wells on Slurm, merged summary checked; $((SECONDS - t0)) s in all"
