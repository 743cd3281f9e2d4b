// The quadrangle smoothing of a planar hybrid mesh (kept_quads.h): each free vertex of the kept
// quadrangles — classified inside a surface (vclass.dim 2), on no line (a written constrained
// edge) and no kept line or point, with a closed star — is moved to the best of a few
// positions: the Laplacian one (the mean of its edge neighbours), the mean of its elements'
// centroids, each also a half and a quarter of the way, then, where its star's minimum scaled
// Jacobian (quad_scaled_jacobian.h) is below compass_below, a compass search from the best (8
// directions, from a tenth of its star's shortest edge, halved) that raises it.
//
// check: every quadrangle of the star strictly convex (exact orient2d on its 4 corner triangles,
// quad_strictly_convex; one that was not convex before may stay so, its scaled Jacobian not
// lower) and every triangle of the star positive (exact orient2d): a vertex shared by triangles
// and quadrangles checks both sides.
// accept: over the star's quadrangles, the minimum scaled Jacobian and the minimum angle do not
// fall and the maximum angle does not rise (with guard_sum, nor does the sum of their scaled
// Jacobians fall); over its triangles, the minimum and the sum of Q and the minimum angle do not
// fall and the maximum angle does not rise; and the star's minimum scaled Jacobian rises (by
// more than 1e-9), or their sum does (by more than 1e-4). The quadrangles' average scaled
// Jacobian must not end below the input's: a run that ends below it is made again with
// guard_sum.
// apply: the vertex's coordinates; connectivity never changes.
// So none of the mesh's quality rows (quadrangles: minimum and average scaled Jacobian, minimum
// and maximum angle; triangles: minimum and average Q, minimum and maximum angle) gets worse.
// Serial, in vertex order: the result depends on the input only. After the first pass, only the
// vertices of the stars that changed are tried again.
#pragma once
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

struct SmoothQuads2dOptions {
  int max_passes = 20;  // sweeps over the free vertices; stops earlier when none moves
  int compass_halvings = 6;
  double compass_below = 0.9;  // the compass search runs where the star's minimum is below it
  // Also refuse a move that lowers the sum of its star's scaled Jacobians. Without it (the
  // default), a run whose average scaled Jacobian ends below the input's is made again with it.
  bool guard_sum = false;
};

struct SmoothQuads2dStats {
  int nb_free = 0;    // free vertices of the quadrangles
  long nb_moves = 0;  // accepted moves, over all passes
  int passes = 0;
  bool sum_guarded = false;  // the run was made again with guard_sum
};

// mesh: a valid planar mesh (check_mesh), its vertices not pinned (pin_vertices.h: a pinned
// vertex is not free). Without kept quadrangles, nothing happens.
SmoothQuads2dStats smooth_quads2d(TriMesh2& mesh, const SmoothQuads2dOptions& options = {});

}  // namespace cvtmesh
