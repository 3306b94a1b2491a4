#!/usr/bin/env bash
# The field examples on a real Slurm: starts a one-node cluster on this machine
# (local_slurm.sh), submits a 20-well synthetic field with examples/cluster/submit-field.sh
# (the array job field.sbatch and its merge job), waits, and checks every well's outputs
# and the merged summary. Fails, with the daemons' logs, if the cluster does not come up.
#   tests/cluster/slurm_field_test.sh CALIPER3D SOURCE_DIR
# Takes about 35 s on a 2-core machine (the wells are short; most of it is Slurm's
# one-second scheduling cadence).
set -euo pipefail
caliper3d=$(realpath "${1:?usage: slurm_field_test.sh CALIPER3D SOURCE_DIR}")
src=$(realpath "${2:?usage: slurm_field_test.sh CALIPER3D SOURCE_DIR}")
wells=${FIELD_WELLS:-20}
limit_s=${FIELD_TIMEOUT_S:-150}

# shellcheck source-path=SCRIPTDIR source=local_slurm.sh
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

# The field: short synthetic wells (the profiles in turn) and their manifest, from synth.
"$caliper3d" synth --field "$wells" --length 60 --step 0.05 -o "$work/field/" >/dev/null
manifest="$work/field/manifest.csv"
mapfile -t files < <(tail -n +2 "$manifest" | cut -d, -f1)
[ "${#files[@]}" -eq "$wells" ] || fail "synth --field $wells wrote ${#files[@]} manifest rows"
export CALIPER3D="$caliper3d"

local_slurm_start "$work/slurm" 2 || fail "the one-node Slurm cluster did not start (logs above)"
echo "cluster up after $((SECONDS - t0)) s"
jobcomp="$work/slurm/log/jobcomp.txt"

# Submits the field from a fresh folder with ROWS_PER_TASK rows per array index, waits, and
# checks what Slurm recorded, every well's report and the merged summary.
runField() {
  local per_task=$1 run="$work/run-$1" t_submit=$SECONDS
  mkdir -p "$run"
  cd "$run"
  local submitted array merge tasks
  submitted=$(ROWS_PER_TASK=$per_task "$src/examples/cluster/submit-field.sh" "$manifest" -o out/) ||
    fail "submit-field.sh: $submitted"
  echo "$submitted"
  array=$(sed -n 's/.*job \([0-9]*\);.*/\1/p' <<<"$submitted")
  merge=$(sed -n 's/.*merge job \([0-9]*\)$/\1/p' <<<"$submitted")
  if ! local_slurm_wait_idle "$limit_s"; then
    local_slurm_logs
    fail "the field did not finish within $limit_s s"
  fi
  echo "ROWS_PER_TASK=$per_task: the field ran in $((SECONDS - t_submit)) s"

  # Every array task and the merge job COMPLETED, as Slurm's job completion log says.
  tasks=$(((wells + per_task - 1) / per_task))
  local done_tasks
  done_tasks=$(grep "ArrayJobId=$array " "$jobcomp" | grep 'JobState=COMPLETED' |
    grep -o 'ArrayTaskId=[0-9]*' | cut -d= -f2 | sort -n | tr '\n' ' ' || true)
  if [ "$done_tasks" != "$(seq -s ' ' 0 $((tasks - 1))) " ]; then
    grep "ArrayJobId=$array " "$jobcomp" >&2 || true
    tail -n 20 logs/*.out >&2 || true
    fail "array tasks completed: '$done_tasks', expected 0 to $((tasks - 1))"
  fi
  grep -q "JobId=$merge .*JobState=COMPLETED" "$jobcomp" ||
    fail "merge job $merge: $(grep "JobId=$merge " "$jobcomp"; cat logs/field-merge-*.out)"

  # Each well's report: present, the report header and a row per section.
  local i out
  for ((i = 0; i < wells; i++)); do
    out="out/$(basename "${files[i]}" .las).csv"
    [ -s "$out" ] || fail "no $run/$out"
    [ "$(wc -l <"$out")" -gt 1000 ] || fail "$out has $(wc -l <"$out") lines"
    head -n 1 "$out" | grep -q '^md_m,' || fail "$out does not start with the report header"
  done

  # The merged summary: one line per row, in manifest order, each ok and naming its file.
  local merged=field-summary.jsonl row=0 line
  [ -f "$merged" ] || fail "no merged summary $run/$merged"
  [ "$(wc -l <"$merged")" -eq "$wells" ] || fail "$merged has $(wc -l <"$merged") lines, not $wells"
  while IFS= read -r line; do
    [[ $line == "{\"row\":$row,"* ]] || fail "summary line $row is not row $row: $line"
    # The summary names the file as batch resolved it, against the manifest's folder.
    [[ $line == *"\"file\":\"$work/field/${files[row]}\""* ]] || fail "summary line $row does not name ${files[row]}: $line"
    [[ $line =~ \"status\":\ *\"ok\" ]] || fail "summary line $row is not ok: $line"
    row=$((row + 1))
  done <"$merged"
  grep -q "$wells lines for $wells wells, 0 not ok, 0 with no line" logs/field-merge-*.out ||
    fail "merge job said: $(cat logs/field-merge-*.out)"
}

# One index per row (the plain case), then blocks of 7 rows: 3 tasks, the last one short.
runField 1
runField 7

# A field with a bad row: its task fails, the merge still runs (afterany), keeps every other
# well's line and says which row failed.
bad_manifest="$work/field/with-bad-row.csv"
{ cat "$manifest"; echo "no-such-well.las,report,"; } >"$bad_manifest"
mkdir -p "$work/run-bad" && cd "$work/run-bad"
submitted=$(ROWS_PER_TASK=7 "$src/examples/cluster/submit-field.sh" "$bad_manifest" -o out/) ||
  fail "submit-field.sh: $submitted"
echo "$submitted (the last row names a missing file)"
local_slurm_wait_idle "$limit_s" || fail "the field with a bad row did not finish within $limit_s s"
[ "$(wc -l <field-summary.jsonl)" -eq $((wells + 1)) ] ||
  fail "merged summary of the bad field: $(wc -l <field-summary.jsonl) lines, not $((wells + 1))"
[ "$(grep -c '"status":"ok"' field-summary.jsonl)" -eq "$wells" ] || fail "the good rows are not all ok"
tail -n 1 field-summary.jsonl | grep -q "^{\"row\":$wells,.*no-such-well.las.*\"status\":\"failed\"" ||
  fail "the bad row's line: $(tail -n 1 field-summary.jsonl)"
grep -q "$((wells + 1)) lines for $((wells + 1)) wells, 1 not ok, 0 with no line" logs/field-merge-*.out ||
  fail "merge job said: $(cat logs/field-merge-*.out)"

passed=1
echo "PASS: $wells wells on Slurm one a task and in blocks, and with a bad row; outputs and merged summaries checked; $((SECONDS - t0)) s in all"
