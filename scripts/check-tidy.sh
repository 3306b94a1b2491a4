#!/usr/bin/env bash
# Runs clang-tidy (.clang-tidy at the root) over the library and app sources with the compile
# commands of BUILD_DIR; fails on any finding, naming it. Two processes at a time.
#   scripts/check-tidy.sh BUILD_DIR
set -euo pipefail
build=$(cd "${1:?usage: check-tidy.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
log="$build/tidy.log"
find io reconstruction scenegraph app -name '*.cpp' -print0 |
  xargs -0 -n 4 -P 2 clang-tidy --quiet -p "$build" >"$log" 2>&1 || true
if grep -iE "(warning|error)[: ]" "$log"; then
  echo "clang-tidy: findings above (full log $log)" >&2
  exit 1
fi
echo "clang-tidy: no findings in io/ reconstruction/ scenegraph/ app/"
