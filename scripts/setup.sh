#!/usr/bin/env bash
# Installs every Debian 12 package cvtmesh needs to build, test and run. Idempotent.
# Run as root (or with sudo available). Usage: scripts/setup.sh
set -euo pipefail
PKGS=(
  build-essential cmake ninja-build pkg-config git
  libgmsh-dev gmsh python3-gmsh gmsh-doc
  libtet1.5-dev tetgen
  libopenmesh-dev
  libgtest-dev libgmock-dev
  libcli11-dev libeigen3-dev nlohmann-json3-dev libpugixml-dev
  libcgal-dev python3-netgen python3-numpy
  libmetis-dev libopenmpi-dev openmpi-bin
  pybind11-dev python3-dev python3 python3-meshio python3-scipy
  xvfb xauth xdotool imagemagick librsvg2-bin
  clang libclang-rt-14-dev
)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PKGS[@]} packages already installed"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
