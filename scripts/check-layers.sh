#!/usr/bin/env bash
# Fails when an #include goes up a layer (app -> scenegraph -> reconstruction -> io), or when io/
# or reconstruction/ reach Coin, Qt or OpenGL, or scenegraph/ reaches Qt, or when the geometry half
# of reconstruction/ (section/, path/, mesh/, parallel/, synthetic/, well_geometry) reaches the
# analysis half (analysis/) or the loading of a well, which sit above it. The CMake targets cannot
# enforce this on their own: Debian installs Coin's headers on the default include path, and every
# target sees the project root. Each module's tests follow the module's rule. Inside app/, the
# command line (app/*) includes no desktop file (app/desktop/), and the desktop includes no
# command-line file but what both programs share: the option table (app/well_option_table.h,
# app/input_options.h) and holding a field lean (app/lean_well.h); view_command.cpp and main.cpp
# are the bridge between them.
#   scripts/check-layers.sh [ROOT]      check the tree at ROOT (default: this checkout)
#   scripts/check-layers.sh --self-test  prove that the check catches each kind of violation
set -euo pipefail

# What each module may not include, as an extended regular expression on the included path.
coinQtGl='Inventor/|Q[A-Za-z]+($|/|\.h)|Qt[A-Za-z]*/|GL/|EGL/|GLES'
declare -A forbidden=(
  [io]="^(reconstruction|scenegraph|app)/|^(${coinQtGl})"
  [reconstruction]="^(scenegraph|app)/|^(${coinQtGl})"
  [scenegraph]="^app/|^(Q[A-Za-z]+($|/|\.h)|Qt[A-Za-z]*/|Inventor/Qt/)"
)
# Inside reconstruction/: geometry (caliper3d_geometry) below analysis (caliper3d_analysis) below
# loading (caliper3d_reconstruction).
geometryForbidden="^reconstruction/(analysis/|load/)|^(scenegraph|app)/|^(${coinQtGl})"
geometryDirs="reconstruction/section reconstruction/path reconstruction/mesh reconstruction/parallel reconstruction/synthetic"
# app/: the two programs.
optionTable='app/(input_options|well_option_table|lean_well)\.h'
commandLineForbidden='^app/desktop/'
desktopForbidden="^app/[^/]+$"
bridge='app/(view_command|main)\.cpp'

# Prints "file:line: includes X" for each violation under ROOT; returns 1 if any.
check() {
  local root=$1 status=0 module dir file line path
  for module in io reconstruction scenegraph; do
    for dir in "$root/$module" "$root/tests/$module"; do
      [ -d "$dir" ] || continue
      while IFS= read -r -d '' file; do
        checkFile "$root" "$file" "$module" "${forbidden[$module]}" || status=1
      done < <(find "$dir" -type f \( -name '*.h' -o -name '*.hpp' -o -name '*.cpp' \) -print0)
    done
  done
  local dir
  for dir in $geometryDirs; do
    [ -d "$root/$dir" ] || continue
    while IFS= read -r -d '' file; do
      checkFile "$root" "$file" "${dir#reconstruction/} (geometry)" "$geometryForbidden" || status=1
    done < <(find "$root/$dir" -type f \( -name '*.h' -o -name '*.hpp' -o -name '*.cpp' \) -print0)
  done
  for file in "$root"/reconstruction/well_geometry.*; do
    [ -f "$file" ] || continue
    checkFile "$root" "$file" "well_geometry (geometry)" "$geometryForbidden" || status=1
  done
  for file in "$root"/app/*.h "$root"/app/*.cpp; do
    [ -f "$file" ] || continue
    [[ ${file#"$root"/} =~ ^$bridge$ ]] && continue
    checkFile "$root" "$file" "the command line" "$commandLineForbidden" || status=1
  done
  if [ -d "$root/app/desktop" ]; then
    while IFS= read -r -d '' file; do
      checkFile "$root" "$file" "the desktop" "$desktopForbidden" "^$optionTable$" || status=1
    done < <(find "$root/app/desktop" -type f \( -name '*.h' -o -name '*.cpp' \) -print0)
  fi
  return $status
}

# Prints a violation for each include of FILE that matches the regular expression FORBIDDEN (or
# climbs with ../), unless it matches ALLOWED; returns 1 if any.
checkFile() {
  local root=$1 file=$2 who=$3 forbiddenRe=$4 allowedRe=${5:-'^$'} status=0 line path
  while IFS=: read -r line path; do
    if [[ $path == ../* || ($path =~ $forbiddenRe && ! $path =~ $allowedRe) ]]; then
      echo "${file#"$root"/}:$line: $who may not include $path" >&2
      status=1
    fi
  done < <(grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]' "$file" |
           sed -E 's/^([0-9]+):[^<"]*[<"]([^>"]+)[>"].*/\1:\2/')
  return $status
}

selfTest() {
  local tmp
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' RETURN
  mkdir -p "$tmp/io" "$tmp/reconstruction/mesh" "$tmp/reconstruction/analysis" "$tmp/scenegraph" \
    "$tmp/tests/io" "$tmp/app/desktop"
  printf '#include "reconstruction/well_geometry.h"\n' >"$tmp/reconstruction/analysis/ok.cpp"
  printf '#include <vector>\n#include "io/a.h"\n' >"$tmp/io/ok.cpp"
  printf '#include "reconstruction/mesh/mesh.h"\n#include <glm/vec3.hpp>\n#include <Inventor/SoDB.h>\n' \
    >"$tmp/scenegraph/ok.cpp"
  printf '#include "app/input_options.h"\n#include "app/desktop/desk_model.h"\n#include "scenegraph/well_scene.h"\n' \
    >"$tmp/app/desktop/ok.cpp"
  printf '#include "app/commands.h"\n#include "app/desktop/main_window.h"\n' >"$tmp/app/view_command.cpp"
  printf '#include "app/input_options.h"\n#include "scenegraph/well_scene.h"\n' >"$tmp/app/ok.cpp"
  check "$tmp" 2>/dev/null || { echo "self-test: a clean tree was refused" >&2; return 1; }
  local bad
  for bad in 'io/x.cpp:#include "reconstruction/mesh/mesh.h"' \
             'io/x.h:#include <Inventor/SoDB.h>' \
             'reconstruction/x.cpp:#include <QString>' \
             'reconstruction/x.cpp:#include <QtCore/QString>' \
             'reconstruction/x.cpp:#include "scenegraph/well_scene.h"' \
             'reconstruction/x.cpp:#include <GL/gl.h>' \
             'reconstruction/mesh/x.cpp:#include "reconstruction/analysis/report_writer.h"' \
             'reconstruction/well_geometry.h:#include "reconstruction/analysis/well_analysis.h"' \
             'scenegraph/x.cpp:#include "app/commands.h"' \
             'scenegraph/x.cpp:#include <Inventor/Qt/SoQt.h>' \
             'scenegraph/x.cpp:#include <QImage>' \
             'tests/io/x_test.cpp:#include "scenegraph/iv_export.h"' \
             'io/x.cpp:  #  include "../app/commands.h"' \
             'app/x.cpp:#include "app/desktop/main_window.h"' \
             'app/x.h:#include "app/desktop/desk_model.h"' \
             'app/desktop/x.cpp:#include "app/scene_assembly.h"' \
             'app/desktop/x.h:#include "app/commands.h"'; do
    local file=${bad%%:*} text=${bad#*:}
    printf '%s\n' "$text" >"$tmp/$file"
    if check "$tmp" 2>/dev/null; then
      echo "self-test: not caught: $file: $text" >&2
      return 1
    fi
    rm "$tmp/$file"
  done
  echo "self-test: every violation caught"
}

if [ "${1:-}" = "--self-test" ]; then
  selfTest
else
  root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
  check "$root" && echo "layers: every include points down (app -> scenegraph -> reconstruction -> io)"
fi
