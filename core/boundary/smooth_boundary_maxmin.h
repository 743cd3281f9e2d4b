// Max-min smoothing of the boundary vertices of poor elements (the boundary side of
// smooth_maxmin3): a surface (curve) vertex of a tet with Q < q_below or a dihedral angle below
// angle_below, or of a boundary triangle with Q < tri_below, is moved within its tangent plane
// (along its curve) and projected back onto its entity of the reference geometry, to raise the
// minimum over its star of the tets' Q, their dihedral angles / angle_scale and its boundary
// triangles' Q. Non-smooth ascent along the smallest vector of the hull of the active gradients
// (finite differences), step halved until accepted. A step is kept only if plan_boundary_move
// accepts it (star positively oriented by exact orient3d, fan within the Hausdorff tolerance),
// the objective strictly rises, and the guards hold (a tet or triangle at or above its floor stays
// there, one below it does not fall below the star's minimum before the move). Corners, locked
// and interior vertices never move; connectivity never changes. Serial, in a fixed order.
#pragma once
#include <limits>

#include "core/geometry/boundary_geometry.h"
#include "core/boundary/volume_budget.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct BoundaryMaxMinOptions {
  double q_below = 0.5;
  double angle_below = 30;
  double tri_below = 0.7;  // boundary triangle Q
  double angle_scale = 60;
  double q_floor = 0.5, angle_floor = 30, tri_floor = 0.6;
  double min_gain = 1e-3;
  int passes = 2;
  int max_steps = 20;
  int max_halvings = 10;
  double hausdorff = std::numeric_limits<double>::infinity();  // absolute
  VolumeBudget* volume_budget = nullptr;  // if set, moves stay within it (and are charged to it)
};

struct BoundaryMaxMinStats {
  long nb_tried = 0, nb_moved = 0, nb_steps = 0;
};

// Dead tets (tets[4t] < 0) are ignored; mesh.adj is not needed.
BoundaryMaxMinStats smooth_boundary_maxmin(TetMesh& mesh, const BoundaryModel& model,
                                           const BoundaryMaxMinOptions& options = {});

}  // namespace cvtmesh
