#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine (packages), builds, and runs the whole test suite with CTest.
# Usage: scripts/test.sh      (as root, or a user with sudo)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
cd "${BUILD_DIR:-build}"
ctest --output-on-failure -j "$(nproc)" --timeout 900
# Opt-in (about 10 min more on 2 cores): the suite built with ASan + UBSan (docs/reliability.md).
if [ "${CVTMESH_SANITIZE_TESTS:-0}" = 1 ]; then
  cd - > /dev/null
  scripts/sanitize.sh
fi
