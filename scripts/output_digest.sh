#!/usr/bin/env bash
# Runs every method on the paper's models (cube_sphere, the femur, the 2D quad and washer) with the
# given cvtmesh binary and prints one "model method sha256" line per output .msh. Two builds give
# the same outputs when their digests are equal:
#   scripts/output_digest.sh OLD/cvtmesh > old.txt; scripts/output_digest.sh build/cvtmesh > new.txt
#   diff old.txt new.txt
# Usage: scripts/output_digest.sh [CVTMESH_BINARY] [WORK_DIR]   (FAST=1: skip the femur)
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
