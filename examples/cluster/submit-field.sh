#!/usr/bin/env bash
# Submits a field to Slurm: the array job (field.sbatch: one index per manifest row, or per
# ROWS_PER_TASK rows) and the merge job that waits for it (field-merge.sbatch). Run it from
# the folder that should get logs/, summaries/ and field-summary.jsonl; prints the job ids.
#   examples/cluster/submit-field.sh MANIFEST [BATCH_OPTION...]     e.g. field.csv -o out/
# Slurm options through sbatch's own variables (SBATCH_PARTITION=long SBATCH_ACCOUNT=geo
# SBATCH_TIMELIMIT=2:00:00 ...); CALIPER3D, SUMMARY_DIR, ROWS_PER_TASK and FIELD_SUMMARY
# reach the jobs with the rest of the environment. A CSV manifest's rows are counted here;
# for a JSON manifest set FIELD_ROWS to its number of wells.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
manifest=${1:?usage: submit-field.sh MANIFEST [BATCH_OPTION...]}
if [ -z "${FIELD_ROWS:-}" ]; then
  # Data rows as batch counts them: not blank, not a '#' comment, less the header line.
  FIELD_ROWS=$(($(grep -cv '^[[:space:]]*\(#\|$\)' "$manifest") - 1))
fi
export FIELD_ROWS
[ "$FIELD_ROWS" -gt 0 ] || { echo "$manifest: no data rows" >&2; exit 1; }
summary_dir=${SUMMARY_DIR:-summaries}
# The merge takes every summary in the folder: one left from another run would join this one.
if compgen -G "$summary_dir/*.jsonl" >/dev/null; then
  echo "$summary_dir/ already holds summaries: move them, or set SUMMARY_DIR" >&2
  exit 1
fi
per_task=${ROWS_PER_TASK:-1}
tasks=$(((FIELD_ROWS + per_task - 1) / per_task))
# Slurm does not create the folder of --output; a missing one loses every task's log.
mkdir -p logs "$summary_dir"
array=$(sbatch --parsable --array=0-$((tasks - 1)) "$here/field.sbatch" "$@")
array=${array%%;*} # --parsable prints "id;cluster" on a multi-cluster site
merge=$(sbatch --parsable --dependency=afterany:"$array" "$here/field-merge.sbatch" "$manifest")
echo "field: $FIELD_ROWS rows in $tasks array tasks, job $array; merge job ${merge%%;*}"
