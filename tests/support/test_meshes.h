// Small hand-built meshes and helpers shared by the tests.
#pragma once
#include <string>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh::testing {

// Path of a model in geo/ and of the CLI binary.
std::string geo_path(const std::string& name);
std::string cli_path();
std::string shared_path(const std::string& rel);
// A fresh, empty temporary directory (removed at process exit is not guaranteed).
std::string temp_dir();
// Runs a shell command, returns its exit code; stdout+stderr captured into *output if given.
int run(const std::string& cmd, std::string* output = nullptr);

// The unit cube split into 6 tets around the diagonal (0,0,0)-(1,1,1), 8 vertices, with its 12
// boundary triangles on surface 1, region 1, adjacency built.
TetMesh cube6();
// The unit square split into 2 triangles (plus 4 boundary edges), adjacency built.
TriMesh2 square2();

}  // namespace cvtmesh::testing

namespace cvtmesh::testing {

// The Delaunay tetrahedralization of a point set (TetGen, no constraints): the convex-hull
// triangles become the boundary (surface 1), hull vertices are fixed (class 2), others interior.
TetMesh delaunay_of_points(const std::vector<double>& xyz);

// Points of the body-centred cubic lattice with spacing a (cube corners and centres) in
// [0, n*a]^3.
std::vector<double> bcc_lattice(int n, double a);

}  // namespace cvtmesh::testing
