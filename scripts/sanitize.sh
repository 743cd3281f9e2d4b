#!/usr/bin/env bash
# Builds the test suite with AddressSanitizer + UndefinedBehaviorSanitizer (CVTMESH_SANITIZE=ON)
# into build-asan/ and runs it. Usage: scripts/sanitize.sh [gtest filter]   (default: all tests)
#
# TetGen (libtet) is loaded with dlopen(RTLD_DEEPBIND) to keep it apart from libgmsh's copy of
# TetGen; ASan refuses that flag in its dlopen interceptor, so sanitizer builds call glibc's dlopen
# directly (core/delaunay/tetgen_library.cpp). Arrays that TetGen allocates with operator new
# (through libstdc++ -> ASan's malloc) and we delete[] then look like a malloc/delete[] mismatch:
# alloc_dealloc_mismatch=0. Leaks are checked, minus scripts/lsan.supp (libgmsh's globals and an
# OpenMesh header leak). libgmsh, libtet and OpenMesh are not instrumented: errors inside them are
# not found. Takes ~10 min to build on 2 cores and ~100 s to run (docs/reliability.md).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${SAN_BUILD_DIR:-build-asan}
FILTER=${1:-*}
if [ ! -f "$BUILD/build.ninja" ]; then
  cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCVTMESH_SANITIZE=ON \
    -DCVTMESH_REQUIRE_FRONTENDS=OFF
fi
cmake --build "$BUILD" --target cvtmesh cvtmesh_tests -j "$(nproc)"
export ASAN_OPTIONS=${ASAN_OPTIONS:-alloc_dealloc_mismatch=0}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/scripts/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
"$BUILD/tests/cvtmesh_tests" --gtest_filter="$FILTER" --gtest_brief=1
