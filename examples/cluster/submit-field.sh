#!/usr/bin/env bash
# Submits a field to Slurm: the array job (field.sbatch, one index per manifest row or per
# ROWS_PER_TASK rows) and the merge job that waits for it (field-merge.sbatch). Run it from
# the folder the manifest's relative paths start from; prints the two job ids.
#   examples/cluster/submit-field.sh field.csv [extra sbatch options for both jobs]
# e.g. ... field.csv --partition=long --account=geo; CALIPER3D, SUMMARY_DIR, ROWS_PER_TASK
# and FIELD_SUMMARY pass through to the jobs (sbatch exports the environment).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
manifest=${1:?usage: submit-field.sh MANIFEST [SBATCH_OPTION...]}
shift
rows=$(grep -cv '^[[:space:]]*\(#\|$\)' "$manifest")
rows=$((rows - 1))
[ "$rows" -gt 0 ] || { echo "$manifest: no data rows" >&2; exit 1; }
per_task=${ROWS_PER_TASK:-1}
tasks=$(((rows + per_task - 1) / per_task))
# Slurm does not create the folders of --output; a missing one loses every task's log.
mkdir -p logs "${SUMMARY_DIR:-summaries}"
array=$(sbatch --parsable --array=0-$((tasks - 1)) "$@" "$here/field.sbatch" "$manifest")
array=${array%%;*}
merge=$(sbatch --parsable --dependency=afterany:"$array" "$@" "$here/field-merge.sbatch" "$manifest")
echo "field: $rows rows in $tasks array tasks, job $array; merge job ${merge%%;*}"
