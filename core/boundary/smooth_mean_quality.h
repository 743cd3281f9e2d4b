// Average-quality smoothing (the sum-of-quality objective of Netgen's and Gmsh's optimizers, CGAL's
// ODT): each vertex is moved to raise the sum of Q over the tets of its star, where the max-min
// smoothing (smooth_maxmin3, smooth_boundary_maxmin) only raises the worst. Interior vertices move
// freely; a surface vertex moves within its tangent plane and is projected back onto its patch of
// the reference geometry (a curve vertex along its curve); corners, locked and pinned vertices
// never move. Gradient ascent on the star's sum (analytic gradient of Q), the step halved until
// accepted. A step is kept only if
//  - every tet of the star stays positively oriented (exact orient3d; plan_boundary_move for a
//    boundary vertex),
//  - the sum strictly rises,
//  - the guards hold: no tet of the star falls below min(the star's minimum Q before the move,
//    the Q floor), nor below min(the star's minimum dihedral angle before, the angle floor), no
//    boundary triangle of the fan below min(the fan's minimum Q before, the triangle floor), each
//    floor being max(q_floor / angle_floor / tri_floor, the mesh's minimum at the start); no tet
//    rises above max(the star's maximum dihedral angle before, the ceiling), the ceiling being
//    min(angle_ceiling, the mesh's maximum at the start) (none from 180 on); the time-step guard
//    (time_step_guard.h), when on, as the polish's moves have it. So the global minima of Q, of
//    the dihedral angle and of the boundary triangles' Q never decrease, nor does the maximum
//    dihedral angle rise;
//  - for a boundary vertex, its fan stays within the Hausdorff tolerance (fan_within_tolerance)
//    and the move's volume change within the volume budget (charged to it).
// Connectivity never changes. Each pass moves the interior vertices colour by colour (no two of
// a colour share a tet), each colour in parallel, then the surface and curve vertices one by one in
// vertex order: the result depends on the input only, not on the number of threads.
#pragma once
#include <limits>

#include "core/boundary/volume_budget.h"
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"
#include "core/quality/time_step_guard.h"

namespace cvtmesh {

struct MeanQualityOptions {
  int passes = 2;          // sweeps over the vertices
  int max_steps = 4;       // accepted ascent steps per vertex and pass
  int max_halvings = 6;    // step halvings before a vertex gives up
  double step = 0.1;       // first trial step: this fraction of the star's shortest edge
  double min_gain = 1e-5;  // a move is kept if the star's sum rises by at least this much
  // A vertex is tried only if the mean Q of its star is below this (1: all of them); a boundary
  // vertex (whose moves cost a projection and the Hausdorff check) below boundary_star_below.
  double star_below = 0.95;
  double boundary_star_below = 0.95;
  double q_floor = 0.5, angle_floor = 30, tri_floor = 0.6;  // the guards (see above)
  // Degrees: the maximum dihedral angle's guard (see above); 180 or more: none.
  double angle_ceiling = 150;
  bool interior = true;  // move the interior vertices
  bool boundary = true;  // move the surface and curve vertices
  double hausdorff = std::numeric_limits<double>::infinity();  // absolute
  VolumeBudget* volume_budget = nullptr;  // if set, boundary moves stay within it (charged to it)
  TimeStepGuard dt_guard;                 // off by default
};

struct MeanQualityStats {
  long nb_tried = 0, nb_moved = 0, nb_steps = 0;
  double sum_before = 0, sum_after = 0;  // sum of Q over the live tets
  long nb_tets = 0;                      // the live tets
};

// Dead tets (tets[4t] < 0) are ignored; mesh.adj is not needed. Vertices with vclass.dim < 3 move
// only if `model` makes them movable (model.movable); pass an empty model (no geometry) to move
// the interior only. Throws std::invalid_argument for bad options.
MeanQualityStats smooth_mean_quality(TetMesh& mesh, const BoundaryModel& model,
                                     const MeanQualityOptions& options = {});

// The gradient of tet_quality(a, b, c, d, Measure::kQ) with respect to the position of vertex k
// (0..3) of the tet: g, 3 doubles.
void tet_q_gradient(const double* const p[4], int k, double g[3]);

}  // namespace cvtmesh
