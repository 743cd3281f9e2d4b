#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds, and runs the main job on the bundled cube with a
# sphere (geo/cube_sphere.geo): the quality table, and the mesh written with quality views.
# Usage: scripts/demo.sh      (as root, or a user with sudo). Output in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
mkdir -p out
./build/cvtmesh stats geo/cube_sphere.geo --label "Gmsh default"
./build/cvtmesh convert geo/cube_sphere.geo out/cube_sphere_gmsh.msh --quality
echo "demo: open the result with: gmsh out/cube_sphere_gmsh.msh"
