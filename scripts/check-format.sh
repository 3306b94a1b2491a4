#!/usr/bin/env bash
# Fails when a C++ file of the tree differs from .clang-format (Debian 12's clang-format 14), and
# names each such file. Fix with: scripts/check-format.sh --fix
#   scripts/check-format.sh [--fix] [ROOT]
#   scripts/check-format.sh --self-test   (shows the check fails on a badly formatted file)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
if [ "${1:-}" = "--self-test" ]; then
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  cp "$here/../.clang-format" "$tmp/"
  mkdir -p "$tmp/io"
  printf 'int f(int x) {\n    return x + 1;\n}\n' >"$tmp/io/good.cpp"
  "$here/check-format.sh" "$tmp" >/dev/null || { echo "self-test: a formatted file was refused" >&2; exit 1; }
  printf 'int  f( int x ){return x+1;}\n' >"$tmp/io/bad.cpp"
  if "$here/check-format.sh" "$tmp" 2>"$tmp/out"; then
    echo "self-test: a badly formatted file passed" >&2; exit 1
  fi
  grep -q "io/bad.cpp: not formatted" "$tmp/out" || { echo "self-test: the file was not named" >&2; exit 1; }
  echo "format check self-test: passed"
  exit 0
fi
fix=0
if [ "${1:-}" = "--fix" ]; then fix=1; shift; fi
root=${1:-$(cd "$here/.." && pwd)}
cd "$root"
command -v clang-format >/dev/null || { echo "clang-format not found (scripts/install-deps.sh installs it)" >&2; exit 1; }
mapfile -d '' files < <(find io reconstruction scenegraph app tests bench examples \
  -type f \( -name '*.h' -o -name '*.cpp' \) -not -path 'tests/fuzz/corpus/*' -print0 2>/dev/null)
if [ $fix -eq 1 ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
# Two processes, 16 files each; clang-format names each line that differs.
out=$(printf '%s\0' "${files[@]}" |
  xargs -0 -n 16 -P 2 clang-format --dry-run -Werror 2>&1 >/dev/null || true)
bad=$(printf '%s\n' "$out" | grep -oE '^[^:]+\.(h|cpp):[0-9]+:[0-9]+: error' | cut -d: -f1 | sort -u || true)
if [ -n "$bad" ]; then
  printf '%s: not formatted (run scripts/check-format.sh --fix)\n' $bad >&2
  exit 1
fi
echo "format: ${#files[@]} files follow .clang-format"
