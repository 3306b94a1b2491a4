#!/usr/bin/env bash
# Screenshots of the window (docs/user-guide.md, README.md) under a virtual X server: the bundled
# example at its breakout and the real STAR log of ../shared/data/real (skipped when absent).
# Needs xvfb, xwd (x11-apps) and ImageMagick's convert.
#   scripts/make-window-pictures.sh [BUILD_DIR]     (default build/release)
set -euo pipefail
build=$(cd "${1:-build/release}" && pwd)
root=$(cd "$(dirname "$0")/.." && pwd)
bin="$build/app/caliper3d"
example="$build/examples/example_well.txt"
star="$root/../shared/data/real/1AA072209208W400_WL_0477502_STAR_FIELD.las"
out="$root/docs/images"
mkdir -p "$out"
# A settings folder of its own: a saved layout would change the pictures.
export XDG_CONFIG_HOME
XDG_CONFIG_HOME=$(mktemp -d)
trap 'rm -rf "$XDG_CONFIG_HOME"' EXIT

# shot OUT.png SECONDS ARGS...: opens the window, waits for the load and the analysis, grabs
# the screen and closes the window.
shot() {
  local png=$1 seconds=$2
  shift 2
  xvfb-run -a -s "-screen 0 1600x1000x24" bash -c '
    "$@" & pid=$!
    sleep '"$seconds"'
    xwd -root -silent | convert xwd:- -trim +repage png:'"$png"'
    kill $pid; wait $pid 2>/dev/null || true' _ "$@"
  echo "wrote $png"
}

shot "$out/window-example.png" 20 "$bin" view "$example" --bit-size 8.5in --at 70
if [ -f "$star" ]; then
  shot "$out/window-star.png" 20 "$bin" view "$star" --at 100 --exaggerate 20 --colour-by GR
else
  echo "no $star: the STAR window picture is left as it is" >&2
fi
