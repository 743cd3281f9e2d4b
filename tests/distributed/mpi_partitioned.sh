#!/usr/bin/env bash
# The partitioned optimization under MPI: `mpirun -n 2 cvtmesh-mpi optimize --parts 3` must write
# the same file, byte for byte, as `cvtmesh optimize --parts 3` in one process, and `check` must
# accept it. Usage: mpi_partitioned.sh MPIEXEC CVTMESH CVTMESH_MPI SOURCE_DIR
set -euo pipefail
mpiexec=$1 cli=$2 mpicli=$3 src=$4
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$cli" -q mesh "$src/geo/cube_sphere.geo" --set h=0.1 --set h_ball=0.08 -o "$dir/in.msh" --binary
"$cli" -q optimize "$dir/in.msh" -o "$dir/one.msh" --parts 3
"$mpiexec" --oversubscribe -n 2 -x OMP_NUM_THREADS=1 "$mpicli" optimize "$dir/in.msh" \
  -o "$dir/two.msh" --parts 3 2> "$dir/log"
cat "$dir/log"
grep -q "round 2: 3 parts" "$dir/log"
cmp "$dir/one.msh" "$dir/two.msh"
"$cli" check "$dir/two.msh"
# A failure on the ranks (an unreadable input) is an error exit, not a hang.
if "$mpiexec" --oversubscribe -n 2 "$mpicli" optimize "$dir/none.msh" -o "$dir/x.msh" --parts 2 \
  2> "$dir/err"; then
  echo "a missing input was not refused"; exit 1
fi
grep -q "none.msh" "$dir/err"
test ! -e "$dir/x.msh"
echo "mpi_partitioned: ok"
