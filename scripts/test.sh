#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine (packages), builds, and runs the whole test suite with CTest.
# Usage: scripts/test.sh      (as root, or a user with sudo)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
cd "${BUILD_DIR:-build}"
ctest --output-on-failure -j "$(nproc)" --timeout 900
# Then a part of the suite built with ASan + UBSan (docs/reliability.md: 7.6 min of CPU from
# scratch, 7 min wall on a busy 2-core machine): CVTMESH_SANITIZE_TESTS=0 skips it, =full runs
# the whole suite sanitized instead (more to build).
SAN=${CVTMESH_SANITIZE_TESTS:-subset}
cd - > /dev/null
case "$SAN" in
  0) echo "test.sh: sanitizer run skipped (CVTMESH_SANITIZE_TESTS=0)" ;;
  full) scripts/sanitize.sh full ;;
  1 | subset) scripts/sanitize.sh subset ;;
  *)
    echo "test.sh: CVTMESH_SANITIZE_TESTS must be 0, subset or full (not '$SAN')" >&2
    exit 2
    ;;
esac
