// The optimization of a surface mesh in space (a TetMesh without tets whose `tris` are the
// surface: core/mesh/check_surface_mesh.h) on its reference geometry (BoundaryModel: the CAD
// surfaces and curves through Gmsh, or the input triangulation): rounds of
//  (a) the constrained CVT step of every movable vertex (smooth_surface_vertices, kCentroid),
//  (b) Delaunay edge flips between nearly coplanar triangles of one surface (flip_surface_edges),
//  (c) max-min angle moves of the vertices of the worst triangles (kMaxMin),
// until no vertex moves by more than `tolerance` of the mean edge length and no edge flips, or
// `patience` rounds in a row gain less than 0.01 degree of minimum angle and 1e-4 of Q_min and of
// average Q over the best so far. The
// round with the best triangles (highest minimum angle, then Q_min, then average Q) among those
// not worse than the input on any of them nor on the maximum angle is kept (else the input).
// With fix_vertices nothing moves: only flips of exactly coplanar edges (the surface unchanged).
#pragma once
#include <array>
#include <functional>
#include <limits>
#include <vector>

#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct SurfaceMeshOptions {
  int rounds = 30;
  double relaxation = 1.0;
  double tolerance = 1e-3;
  int patience = 8;  // of the mean edge length: a round moving less has converged
  double hausdorff = std::numeric_limits<double>::infinity();  // absolute
  double flat_angle = 10;                                      // degrees (flips)
  bool fix_vertices = false;
  double worst_fraction = 0.05;  // (c): the vertices of this fraction of the worst triangles
  // Edges never flipped (smaller id first, sorted): the file's line elements.
  std::vector<std::array<int, 2>> kept_edges;
  // Called after each round with the round and the mesh's Q_min and average Q.
  std::function<void(int round, double q_min, double q_avg)> progress;
};

struct SurfaceMeshStats {
  int rounds = 0;      // rounds run
  int best_round = 0;  // the round kept (0: the input)
  bool converged = false;
  long nb_moves = 0, nb_flips = 0;
};

SurfaceMeshStats optimize_surface_mesh(TetMesh& mesh, const BoundaryModel& model,
                                       const SurfaceMeshOptions& options = {});

}  // namespace cvtmesh
