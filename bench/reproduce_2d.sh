#!/usr/bin/env bash
# Runs every 2D experiment of docs/reproduction-2d.md (Release build in build/ expected):
# the main tables and pictures, the accelerated-Lloyd variant, L-BFGS and basin hopping, the seed
# and grading sweeps.
# Usage: bench/reproduce_2d.sh [OUT_DIR]   (default: /tmp/cvtmesh-reproduce-2d; pictures go to
# docs/img/2d). Takes about half an hour on 2 cores (the basin-hopping runs).
set -euo pipefail
cd "$(dirname "$0")/.."
B=${BUILD_DIR:-build}/bench/reproduce_2d
OUT=${1:-/tmp/cvtmesh-reproduce-2d}
mkdir -p "$OUT"
$B --out docs/img/2d > "$OUT/tables.md"
$B --examples washer --methods cvt --relaxation 1.5 --anderson 5 > "$OUT/washer_cvt_accelerated.md"
$B --examples quad --methods cvt --relaxation 1.5 --anderson 5 > "$OUT/quad_cvt_accelerated.md"
for s in 2 3 4 5; do
  $B --examples washer --methods cvt --seed $s > "$OUT/washer_cvt_seed$s.md"
  $B --examples washer --methods cvt --seed $s --relaxation 1.5 --anderson 5 > "$OUT/washer_cvt_accelerated_seed$s.md"
done
# Lower-energy CVTs (docs/reproduction-2d.md, "Reaching the target"): L-BFGS and basin hopping.
$B --examples washer --methods cvt --lbfgs 7 > "$OUT/washer_cvt_lbfgs.md"
$B --examples quad --methods cvt --lbfgs 7 --hops 20 > "$OUT/quad_cvt_lbfgs_hops20.md"
$B --examples washer --methods cvt --lbfgs 7 --hops 20 --out docs/img/2d > "$OUT/washer_cvt_lbfgs_hops20.md"
$B --examples washer --methods cvt --relaxation 1.5 --anderson 5 --hops 20 > "$OUT/washer_cvt_accelerated_hops20.md"
$B --examples washer --methods cvt --hops 20 > "$OUT/washer_cvt_plain_hops20.md"
$B --examples washer --methods cvt --hops 40 > "$OUT/washer_cvt_plain_hops40.md"
for a in 0.15 0.3 0.5; do
  $B --examples washer --methods cvt --relaxation 1.5 --anderson 5 --hops 10 --hop-amount $a > "$OUT/washer_cvt_accelerated_hops10_amount$a.md"
done
$B --examples washer --methods cvt --relaxation 1.5 --anderson 5 --hops 30 > "$OUT/washer_cvt_accelerated_hops30.md"
for s in 2 3 4 5; do
  $B --examples washer --methods cvt --seed $s --lbfgs 7 --hops 20 > "$OUT/washer_cvt_lbfgs_hops20_seed$s.md"
  $B --examples washer --methods cvt --seed $s --relaxation 1.5 --anderson 5 --hops 20 > "$OUT/washer_cvt_accelerated_hops20_seed$s.md"
done
$B --examples washer --methods cvt --lbfgs 7 --hops 60 > "$OUT/washer_cvt_lbfgs_hops60.md"
$B --examples washer --methods cvt --lbfgs 7 --hops 40 --hop-amount 0.5 > "$OUT/washer_cvt_lbfgs_hops40_amount0.5.md"
for hs in 2 3; do
  $B --examples washer --methods cvt --lbfgs 7 --hops 20 --hop-seed $hs > "$OUT/washer_cvt_lbfgs_hops20_hopseed$hs.md"
done
for hg in "0.06 0.06" "0.1 0.1" "0.08 0.12"; do
  set -- $hg
  $B --examples washer --methods cvt --washer-h0 $1 --washer-g $2 > "$OUT/washer_cvt_h0_$1_g_$2.md"
done
echo "results in $OUT"
