#!/usr/bin/env bash
# Installs the Debian 12 packages caliper3d needs to build, run and test.
# Idempotent: does nothing (and needs no network) when all are present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config
  libcoin-dev libsoqt520-dev qtbase5-dev libqt5charts5-dev libboost-dev libglm-dev
  libgtest-dev libbenchmark-dev libfast-float-dev libassimp-dev libtinygltf-dev
  nlohmann-json3-dev libpng-dev libgeographiclib-dev libproj-dev
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  xvfb xauth clang libclang-rt-14-dev clang-format clang-tidy locales
  # A one-node Slurm for the test of the cluster examples (tests/cluster/slurm_field_test.sh).
  slurm-wlm munge
  # Reads the Kubernetes examples in tests/cluster/k8s_field_test.sh.
  python3-yaml
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# A comma-decimal locale for the test that the report's numbers do not follow the locale
# (tests/app/report_locale_test.cpp).
generateTestLocale() {
  locale -a 2>/dev/null | grep -qi '^de_DE\.utf-\?8$' && return 0
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo localedef -i de_DE -f UTF-8 de_DE.UTF-8 || echo "warning: could not generate de_DE.UTF-8" >&2
}

if [ ${#missing[@]} -eq 0 ]; then
  generateTestLocale
  exit 0
fi

echo "Installing: ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
generateTestLocale
