#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds, and runs the main job on the bundled cube with a
# sphere (geo/cube_sphere.geo): the paper's Table 6 (Init | CombOpt | CVDT | CVDT+SWAP) plus our
# CVDT+SWAP+smooth and the peers (Gmsh, TetGen, Netgen, CGAL) on the same initial mesh, and every mesh
# written with its per-element quality views into out/cube_sphere/.
# Usage: scripts/demo.sh      (as root, or a user with sudo)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
mkdir -p out/cube_sphere
./build/cvtmesh compare geo/cube_sphere.geo --save out/cube_sphere | tee out/cube_sphere/table.txt
echo "demo: the meshes are in out/cube_sphere/ (open one with: gmsh out/cube_sphere/cvdt_swap_smooth.msh)"
