// Small hand-built meshes and helpers shared by the tests.
#pragma once
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/mesh_data.h"
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
// As root: "setpriv --reuid=65534 --regid=65534 --clear-groups " (util-linux), a command prefix
// that runs the CLI as user nobody, to whom file permissions apply, if nobody can run the CLI
// where it is built. "" when not root or when that is not possible (tests then skip).
std::string unprivileged_prefix();

// A mesh from points and tets (each reordered to be positively oriented), one region, adjacency
// built, and its boundary faces as the constrained triangles (surface 1). Vertices listed in
// `interior` get vclass.dim 3, the others 2.
TetMesh make_tet_mesh(const std::vector<std::array<double, 3>>& points,
                      const std::vector<std::array<int, 4>>& tets,
                      const std::vector<int>& interior = {});

// geo/cube_sphere.geo meshed by Gmsh with edge lengths h (far) and h_ball; Gmsh's optimizer off
// (the paper's Init) unless gmsh_optimize; extra .geo numbers (e.g. {"two_regions", 1}).
MeshData cube_sphere(double h, double h_ball, bool gmsh_optimize = false,
                     const std::vector<std::pair<std::string, double>>& extra = {});

// Largest distance from a vertex of a to the nearest vertex of b (2D meshes).
double max_nearest_distance(const TriMesh2& a, const TriMesh2& b);

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

// The (n+1)^3 points of the cube lattice of spacing 1 in [0, n]^3, every interior point moved by
// up to `jitter` in each coordinate (uniformly, a fixed seed) if jitter > 0.
std::vector<double> cube_lattice(int n, double jitter = 0);

// cube_lattice(3) plus points exactly on its hull: the midpoints of the bottom face's grid edges
// and the centres of the top face's squares.
std::vector<double> cube_lattice_with_hull_points();

// The Delaunay tetrahedralization of the (n+1)^3 lattice points of [0, n]^3 (spacing 1), each
// coordinate not on the box's faces jittered by up to `amount` (a point stays within its own face
// or edge, corners exact), from a linear congruential generator seeded with `seed`: deterministic.
TetMesh jittered_box(int n, double amount, unsigned seed);

}  // namespace cvtmesh::testing
