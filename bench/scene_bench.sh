#!/usr/bin/env bash
# The scene at scale, as a timed command-line run: for wells of 10 m, 100 m, 1 km and 4 km
# logged every 2.5 mm (synth profile "example"), `caliper3d render --stats` at 1280x800 from
# two cameras: down the hole from 1 m below the top of the log, and the iso view of the whole
# well. Prints one table row per well and view; docs/benchmarks.md records them.
#   bench/scene_bench.sh [BUILD_DIR] [LENGTHS...]
# Runs on llvmpipe without a display (EGL surfaceless), or on a GPU where one is at hand.
set -euo pipefail
build=${1:-build/release}
shift || true
lengths=("$@")
[ ${#lengths[@]} -gt 0 ] || lengths=(10 100 1000 4000)
bin="$build/app/caliper3d"
work=${SCENE_BENCH_DIR:-$(mktemp -d)}
echo "| length_m | view | sections | segments | triangles_full | triangles_drawn | nodes_traversed | frame_ms | first_picture_ms | load_ms | rss_mb |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for length in "${lengths[@]}"; do
  log="$work/well_${length}m.txt"
  [ -f "$log" ] || "$bin" synth -o "$log" --length "$length" --step 0.0025 >/dev/null
  for view in hole iso; do
    args=(--view "$view")
    [ "$view" = hole ] && args+=(--at 1)
    out=$("$bin" render "$log" -o "$work/picture.png" --width 1280 --height 800 "${args[@]}" --stats)
    well=$(printf '%s\n' "$out" | grep -m1 ' sections, ')
    stats=$(printf '%s\n' "$out" | grep -m1 '^triangles_drawn=')
    sections=$(printf '%s' "$well" | sed -E 's/.*: ([0-9]+) sections.*/\1/')
    segments=$(printf '%s' "$well" | sed -E 's/.* ([0-9]+) segments.*/\1/')
    full=$(printf '%s' "$well" | sed -E 's/.* ([0-9]+) triangles at full detail.*/\1/')
    value() { printf '%s' "$stats" | sed -E "s/.*$1=([0-9.]+).*/\\1/"; }
    echo "| $length | $view | $sections | $segments | $full | $(value triangles_drawn) | $(value nodes_traversed) | $(value frame_ms) | $(value first_picture_ms) | $(value load_ms) | $(value rss_mb) |"
  done
done
[ -n "${SCENE_BENCH_DIR:-}" ] || rm -rf "$work"
