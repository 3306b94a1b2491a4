#!/usr/bin/env bash
# A field in one scene, as a timed command-line run: N wells of 1 km (synth --field: named
# wells at their header places, 25 m apart on a ring, drilled outwards) logged every STEP
# metres, drawn by `caliper3d render --stats` at 1280x800 in the overview (iso, every well
# framed) and down the first well's hole (1 m below its top), and opened in the window by
# `caliper3d view --stats` (under xvfb-run without a display; its load_ms is every well loaded,
# its peak RSS taken once the window has settled; stderr says when that was, and when the
# window, once made, opened its wells: the open its first picture is due within 1 s of).
# Beside it, the time `caliper3d info` takes to read every file (a plain parse of the field: info
# reads each log whole), so load_ms reads against it. Prints one table row per field and view;
# docs/benchmarks.md records them.
#   bench/field_scene_bench.sh [BUILD_DIR] [WELLS:STEP ...]      (default: 20:0.1 100:0.1 20:0.0025)
# Runs on llvmpipe without a display (EGL surfaceless), or on a GPU where one is at hand.
set -euo pipefail
build=${1:-build/release}
shift || true
fields=("$@")
[ ${#fields[@]} -gt 0 ] || fields=(20:0.1 100:0.1 20:0.0025)
bin="$build/app/caliper3d"
work=${FIELD_BENCH_DIR:-$(mktemp -d)}
echo "| wells | step_m | view | parse_s | triangles_drawn | nodes_traversed | frame_ms | first_picture_ms | load_ms | rss_mb |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for field in "${fields[@]}"; do
  wells=${field%%:*}
  step=${field##*:}
  dir="$work/field_${wells}_${step}"
  [ -f "$dir/manifest.csv" ] || "$bin" synth --field "$wells" -o "$dir/" --length 1000 --step "$step" >/dev/null
  start=$(date +%s%N)
  "$bin" info "$dir"/*.las >/dev/null
  parse_ms=$((($(date +%s%N) - start) / 1000000))
  for view in iso hole; do
    args=(--view "$view")
    [ "$view" = hole ] && args+=(--at 1)
    stats=$("$bin" render "$dir"/*.las -o "$work/field.png" --width 1280 --height 800 "${args[@]}" --stats |
      grep -m1 '^triangles_drawn=')
    value() { printf '%s' "$stats" | sed -E "s/.*$1=([0-9.]+).*/\\1/"; }
    printf '| %s | %s | %s | %d.%03d | %s | %s | %s | %s | %s | %s |\n' "$wells" "$step" "$view" \
      $((parse_ms / 1000)) $((parse_ms % 1000)) \
      "$(value triangles_drawn)" "$(value nodes_traversed)" "$(value frame_ms)" \
      "$(value first_picture_ms)" "$(value load_ms)" "$(value rss_mb)"
  done
  # The window opening the field (under Xvfb where there is no display): its first frame with a
  # well in it and every well loaded, from the start of the command (view --stats).
  if [ -n "${DISPLAY:-}" ] || command -v xvfb-run >/dev/null; then
    runner=()
    [ -n "${DISPLAY:-}" ] || runner=(xvfb-run -a -s "-screen 0 1280x800x24")
    stats=$("${runner[@]}" "$bin" view --stats "$dir"/*.las 2>/dev/null | grep -m1 '^first_picture_ms=')
    printf '| %s | %s | window | %d.%03d | | | | %s | %s | %s |\n' "$wells" "$step" \
      $((parse_ms / 1000)) $((parse_ms % 1000)) \
      "$(value first_picture_ms)" "$(value complete_ms)" "$(value rss_mb)"
    echo "$wells wells at $step m: the window opened its wells at $(value open_ms) ms (first picture $(($(value first_picture_ms) - $(value open_ms))) ms after) and settled (every well analysed or held lean) at $(value settled_ms) ms" >&2
  fi
done
[ -n "${FIELD_BENCH_DIR:-}" ] || rm -rf "$work"
