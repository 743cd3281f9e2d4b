#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/: our Medit, TetGen, VTK readers, and the .msh path through
# Gmsh) with clang-14 + ASan + UBSan into build-fuzz/ (separate from the main build) and runs each
# for SECONDS seconds (default 600, the issue's 10 minutes) from the seed corpus in
# fuzz/seeds/<target>.
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]      (targets: medit tetgen vtk msh)
# New inputs go to build-fuzz/corpus/<target>; a crasher is written as build-fuzz/crash-* and the
# run stops with a non-zero exit: minimize it, fix the reader, and commit the input to
# tests/bad_input/files/ (the CLI corpus test then keeps it refused cleanly).
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH=${1:-600}
shift || true
TARGETS=("$@")
[ ${#TARGETS[@]} -gt 0 ] || TARGETS=(medit tetgen vtk msh)
BUILD=${FUZZ_BUILD_DIR:-build-fuzz}
if [ ! -f "$BUILD/build.ninja" ]; then
  cmake -S fuzz -B "$BUILD" -G Ninja -DCMAKE_CXX_COMPILER=clang++-14
fi
cmake --build "$BUILD" -j "$(nproc)"
# fuzz_msh has libgmsh and libtet in the process: the options of scripts/sanitize.sh (TetGen's
# new[]/delete[] across the ASan boundary, libgmsh's globals kept until exit).
export ASAN_OPTIONS=${ASAN_OPTIONS:-alloc_dealloc_mismatch=0}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/scripts/lsan.supp:print_suppressions=0}
for t in "${TARGETS[@]}"; do
  mkdir -p "$BUILD/corpus/$t"
  echo "== fuzz_$t for ${SECONDS_EACH}s"
  # Readers allocate what a file declares only after bounding it by the file size, so 512 MB of
  # RSS is a finding; inputs up to 64 kB reach every section of our formats.
  (cd "$BUILD" && "./fuzz_$t" -max_total_time="$SECONDS_EACH" -rss_limit_mb=512 -max_len=65536 \
    -timeout=10 -print_final_stats=1 "corpus/$t" "../fuzz/seeds/$t")
done
