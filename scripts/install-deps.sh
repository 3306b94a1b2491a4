#!/usr/bin/env bash
# Installs the Debian 12 packages caliper3d needs to build, run and test.
# Idempotent: does nothing (and needs no network) when all are present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config
  libcoin-dev libsoqt520-dev qtbase5-dev libboost-dev libglm-dev
  libgtest-dev libbenchmark-dev libfast-float-dev
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  xvfb xauth clang libclang-rt-14-dev clang-format clang-tidy
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing: ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
