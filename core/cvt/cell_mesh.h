// What the restricted Voronoi cells of one mesh configuration share, computed once per Lloyd
// iteration (per tet, in parallel) instead of once per vertex: the stars, the constrained faces,
// the tet and face circumcentres, and which tets the exact dual decomposition may use.
#pragma once
#include <vector>

#include "core/mesh/face_key.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/vertex_star.h"
#include "core/util/default_init_allocator.h"

namespace cvtmesh {

struct CellMesh {
  VertexStar star;
  std::vector<char> constrained;  // 4*#T: face f of tet t is a boundary or interface triangle
  // #T: t is locally Delaunay (no neighbour's opposite vertex strictly inside its circumsphere,
  // exact insphere) and its circumcentre lies in its region (reached by a short walk that crosses
  // no constrained face). A free vertex whose star tets are all dual_ok has the convex hull of
  // their circumcentres as its Voronoi cell; for a vertex on the boundary, the same decomposition
  // gives its cell cut by the planes of its boundary triangles (see dual_voronoi_cell).
  std::vector<char> dual_ok;
  double eps = 0;  // length tolerance of the clipping (relative to the coordinates)
  // 3*#T: gradient in each tet of the P1 density (when prepared with one).
  std::vector<double> rho_grad;
  // 24*#T: for each dual_ok tet and local vertex k, the integrals (volume, mass, moment x/y/z,
  // energy; relative to that vertex) of the part of the vertex's Voronoi cell dual to the tet
  // (dual_tet_pieces). Computed tet by tet, while the tet's data is in cache. Not zeroed when
  // it grows (only the pieces of dual_ok tets are read, each written first): its pages are first
  // touched by the threads that write them (~200 MB at 1M tets, ~1.9 GB at 10M).
  std::vector<double, DefaultInitAllocator<double>> dual_piece;
};

// `rho`: per-vertex density values (optional; uniform density 1 if null). `unconstrained_delaunay`:
// the caller knows that every unconstrained face is locally Delaunay (restored by flips), so only
// faces with a constraint are tested -- except the faces in `suspect` (sorted vertex ids, e.g. the
// faces the flips could not make Delaunay), whose two tets are tested in full. The same dual_ok
// as testing every face, when the caller's claim holds.
CellMesh prepare_cell_mesh(const TetMesh& mesh, const std::vector<double>* rho = nullptr,
                           bool unconstrained_delaunay = false);
// The same into `out`, reusing its buffers (the Lloyd loop calls it every iteration).
void prepare_cell_mesh(const TetMesh& mesh, const std::vector<double>* rho,
                       bool unconstrained_delaunay, CellMesh& out,
                       const std::vector<FaceKey>* suspect = nullptr);

// The gradient g (3 values) of the linear interpolant over tet t of the per-vertex values rho
// (0 for a flat tet).
void density_gradient(const TetMesh& mesh, int t, const std::vector<double>& rho, double* g);

// 1e-12 times the largest absolute coordinate (at least 1e-12).
double coordinate_eps(const TetMesh& mesh);

}  // namespace cvtmesh
