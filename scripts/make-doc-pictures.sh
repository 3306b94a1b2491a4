#!/usr/bin/env bash
# Renders the pictures docs/user-guide.md and README.md show, with a built caliper3d: the
# bundled example well and the real STAR log of ../shared/data/real (skipped when absent).
#   scripts/make-doc-pictures.sh [BUILD_DIR]     (default build/release)
set -euo pipefail
build=${1:-build/release}
root=$(cd "$(dirname "$0")/.." && pwd)
bin="$build/app/caliper3d"
example="$build/examples/example_well.txt"
star="$root/../shared/data/real/1AA072209208W400_WL_0477502_STAR_FIELD.las"
out="$root/docs/images"
mkdir -p "$out"
size=(--width 900 --height 700)
"$bin" render "$example" -o "$out/example-class.png" "${size[@]}" --view east --exaggerate 40 --colour-by class
"$bin" render "$example" -o "$out/example-diameter.png" "${size[@]}" --view east --exaggerate 40 --colour-by diameter
"$bin" render "$example" -o "$out/example-hole-departure.png" "${size[@]}" --view hole --at 59
if [ -f "$star" ]; then
  "$bin" render "$star" -o "$out/star-departure.png" "${size[@]}" --view east --exaggerate 30
  "$bin" render "$star" -o "$out/star-gr.png" "${size[@]}" --view east --exaggerate 30 --colour-by GR
else
  echo "no $star: the STAR pictures are left as they are" >&2
fi
