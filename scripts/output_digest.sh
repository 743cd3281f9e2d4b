#!/usr/bin/env bash
# Runs every method on the paper's models (cube_sphere, the femur, the 2D quad and washer) with the
# given cvtmesh binary and prints one "model method sha256" line per output .msh. Two builds give
# the same outputs when their digests are equal:
#   scripts/output_digest.sh OLD/cvtmesh > old.txt; scripts/output_digest.sh build/cvtmesh > new.txt
#   diff old.txt new.txt
# Usage: scripts/output_digest.sh [CVTMESH_BINARY] [WORK_DIR]   (FAST=1: skip the femur;
# MINIMISERS=1: also cvdt with the non-default minimisers: 3D relaxed/Anderson and plain Lloyd,
# 3D L-BFGS of another memory, 2D L-BFGS with and without basin hopping)
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=$(realpath "${1:-build/cvtmesh}")
WORK=${2:-$(mktemp -d)}
mkdir -p "$WORK"
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}
models3=(cube_sphere)
[ "${FAST:-0}" = 1 ] || models3+=(femur)
for m in "${models3[@]}"; do
  "$BIN" mesh "geo/$m.geo" -o "$WORK/$m.init.msh" > /dev/null 2>&1
  for meth in cvdt+swap+smooth cvdt+swap cvdt combined swap smooth; do
    "$BIN" optimize "$WORK/$m.init.msh" -o "$WORK/$m.$meth.msh" --method "$meth" > /dev/null 2>&1
    echo "$m $meth $(sha256sum < "$WORK/$m.$meth.msh" | cut -c1-16)"
  done
done
for m in quad washer; do
  "$BIN" mesh "geo/$m.geo" -o "$WORK/$m.init.msh" > /dev/null 2>&1
  for meth in cvdt cvdt+swap dl wdl; do
    "$BIN" optimize "$WORK/$m.init.msh" -o "$WORK/$m.$meth.msh" --method "$meth" > /dev/null 2>&1
    echo "$m $meth $(sha256sum < "$WORK/$m.$meth.msh" | cut -c1-16)"
  done
done
if [ "${MINIMISERS:-0}" = 1 ]; then
  # The output mesh and the per-iteration log (D, energy, quality; timings dropped).
  run() {  # model label args...
    local m=$1 label=$2
    shift 2
    "$BIN" optimize "$WORK/$m.init.msh" -o "$WORK/$m.$label.msh" --method cvdt "$@" \
      2> "$WORK/$m.$label.log" > /dev/null
    local log
    log=$(grep -E '^(lloyd|hop)' "$WORK/$m.$label.log" | sed -E 's/[0-9.]+s\b/_s/g' | sha256sum)
    echo "$m cvdt[$*] $(sha256sum < "$WORK/$m.$label.msh" | cut -c1-16) log ${log:0:16}"
  }
  for m in "${models3[@]}"; do
    run "$m" lbfgs --lbfgs 5
    run "$m" anderson --lbfgs 0
    run "$m" plain --lbfgs 0 --anderson 0 --relaxation 1
    run "$m" lbfgs2 --lbfgs 2 --relaxation 1
  done
  # 2D: the paper's perturbed quad (RandPert, ClusPert) and the washer.
  "$BIN" perturb "$WORK/quad.init.msh" -o "$WORK/quad_rand.init.msh" --random --seed 3 > /dev/null 2>&1
  "$BIN" perturb "$WORK/quad.init.msh" -o "$WORK/quad_clus.init.msh" --cluster > /dev/null 2>&1
  for m in quad_rand quad_clus washer; do
    run "$m" lbfgs --lbfgs 5
    run "$m" lbfgs_hops --lbfgs 3 --hops 2
    run "$m" anderson --anderson 5 --relaxation 1.5
    run "$m" plain --anderson 0 --relaxation 1
  done
fi
