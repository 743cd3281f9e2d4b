#!/usr/bin/env bash
# Configures (Release by default) and builds cvtmesh into build/ (incremental).
# Usage: scripts/build.sh [extra cmake args]   (BUILD_DIR=... to choose another build dir)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
if [ ! -f "$BUILD_DIR/build.ninja" ]; then
  cmake -S . -B "$BUILD_DIR" -G Ninja "$@"
elif [ $# -gt 0 ]; then
  cmake -S . -B "$BUILD_DIR" "$@"
fi
cmake --build "$BUILD_DIR" -j "$(nproc)"
