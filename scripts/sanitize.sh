#!/usr/bin/env bash
# Builds tests with AddressSanitizer + UndefinedBehaviorSanitizer (CVTMESH_SANITIZE=ON, -O1 -g1)
# into build-asan/ and runs them.
# Usage: scripts/sanitize.sh [subset|full] [gtest filter]
#   subset (default, what scripts/test.sh runs): cvtmesh_san_tests, the part of the suite listed in
#          tests/CMakeLists.txt (CVTMESH_SANITIZE_SUBSET); 7.6 min of CPU from scratch.
#   full:  the whole cvtmesh_tests (12 more test files to build).
# Both run the sanitized `cvtmesh` where a test calls the CLI (bad-input corpus, determinism).
#
# TetGen (libtet) is loaded with dlopen(RTLD_DEEPBIND) to keep it apart from libgmsh's copy of
# TetGen; ASan refuses that flag in its dlopen interceptor, so sanitizer builds call glibc's dlopen
# directly (core/geometry/tetgen_library.cpp). Arrays that TetGen allocates with operator new
# (through libstdc++ -> ASan's malloc) and we delete[] then look like a malloc/delete[] mismatch:
# alloc_dealloc_mismatch=0. Leaks are checked, minus scripts/lsan.supp (libgmsh's globals and an
# OpenMesh header leak). libgmsh, libtet and OpenMesh are not instrumented: errors inside them are
# not found. Figures and the choice of the subset: docs/reliability.md.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${SAN_BUILD_DIR:-build-asan}
MODE=${1:-subset}
FILTER=${2:-*}
case "$MODE" in
  subset) TARGET=cvtmesh_san_tests ;;
  full) TARGET=cvtmesh_tests ;;
  *)
    echo "usage: scripts/sanitize.sh [subset|full] [gtest filter]" >&2
    exit 2
    ;;
esac
# -O1 -g1 (line tables only): a third of the compile time of -O2 -g, stack traces keep file:line.
cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCVTMESH_SANITIZE=ON \
  -DCVTMESH_REQUIRE_FRONTENDS=OFF > /dev/null
cmake --build "$BUILD" --target cvtmesh "$TARGET" -j "$(nproc)"
export ASAN_OPTIONS=${ASAN_OPTIONS:-alloc_dealloc_mismatch=0}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/scripts/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
"$BUILD/tests/$TARGET" --gtest_filter="$FILTER" --gtest_brief=1
