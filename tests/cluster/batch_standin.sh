#!/usr/bin/env bash
# Stand-in for `caliper3d batch MANIFEST --row K --summary FILE` while the batch verb is not
# in this build: runs `caliper3d report` on row K of a manifest with the columns
# file,verbs,survey,wellhead,bit_size,overrides,output (simple CSV, no quoted commas) and
# writes a one-line JSON summary. Any other verb goes to the real program ($CALIPER3D_REAL).
set -euo pipefail
real=${CALIPER3D_REAL:?CALIPER3D_REAL names the real caliper3d}
[ "${1:-}" = batch ] || exec "$real" "$@"
manifest=$2
shift 2
row="" summary=""
while [ $# -gt 0 ]; do
  case $1 in
    --row) row=$2; shift 2 ;;
    --summary) summary=$2; shift 2 ;;
    *) echo "batch stand-in: unknown option $1" >&2; exit 2 ;;
  esac
done
line=$(grep -v '^[[:space:]]*\(#\|$\)' "$manifest" | sed -n "$((row + 2))p")
[ -n "$line" ] || { echo "batch stand-in: no row $row in $manifest" >&2; exit 2; }
IFS=, read -r file _verbs _survey _wellhead bit_size _overrides output <<<"$line"
args=()
[ -n "$bit_size" ] && args+=(--bit-size "$bit_size")
start=$(date +%s.%N)
status=ok
"$real" report "$file" -o "$output" "${args[@]}" >/dev/null || status=error
end=$(date +%s.%N)
printf '{"row":%d,"file":"%s","status":"%s","outputs":["%s"],"seconds":%.3f}\n' \
  "$row" "$file" "$status" "$output" "$(awk -v a="$start" -v b="$end" 'BEGIN {print b - a}')" >"$summary"
[ "$status" = ok ]
