#!/usr/bin/env bash
# Fails when a C++ file of the tree differs from .clang-format (Debian 12's clang-format 14), and
# names each such file. Fix with: scripts/check-format.sh --fix
#   scripts/check-format.sh [--fix] [ROOT]
set -euo pipefail
fix=0
if [ "${1:-}" = "--fix" ]; then fix=1; shift; fi
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"
mapfile -d '' files < <(find io reconstruction scenegraph app tests bench examples \
  -type f \( -name '*.h' -o -name '*.cpp' \) -not -path 'tests/fuzz/corpus/*' -print0 2>/dev/null)
if [ $fix -eq 1 ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
bad=0
for f in "${files[@]}"; do
  if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then
    echo "$f: not formatted (run scripts/check-format.sh --fix)" >&2
    bad=1
  fi
done
[ $bad -eq 0 ] && echo "format: ${#files[@]} files follow .clang-format"
exit $bad
