#!/usr/bin/env bash
# Runs every test of a build folder with ctest under a virtual X server
# (the GL tests need one; the rest do not care).
set -euo pipefail
build=${1:?usage: run-tests.sh BUILD_DIR}
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0}
export QT_QPA_PLATFORM=xcb
# -noreset: the server otherwise resets whenever its last client leaves, and a test
# that connects during that reset is refused (two tests run at once).
exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  ctest --test-dir "$build" --output-on-failure --timeout 600 -j2
