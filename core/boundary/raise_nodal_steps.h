// Raising the lowest nodal time steps (issue 17: the global explicit time step of the result never
// below the input's). The global step of P1 elements with lumped mass nearly equals the smallest
// nodal step (vertex_time_step.h) when its largest mode sits at one vertex -- after the free
// boundary, a surface or curve vertex with a few flat tets around it (Gmsh t20: a curve vertex of
// 3 tets, 0.68x the input's global step; igl_cheburashka: a surface vertex of 1 tet). For each
// vertex v whose nodal step is below `target`, lowest first, v and each vertex sharing a tet with
// it are moved in turn by a pattern search (pattern_move.h: interior vertices in space, surface
// vertices in their fan's tangent plane, curve vertices along their curve, each projected onto its
// entity of the reference geometry) on the mover's star's minimum over its vertices of min(nodal
// step, target): a vertex above the target may come down to it, none below it falls. A position is
// taken only if:
//  - every tet of the mover's star stays positively oriented (exact orient3d) and, for a boundary
//    vertex, plan_boundary_move accepts it (no fold, the fan within the Hausdorff tolerance) and
//    the volume budget admits it;
//  - every tet of the star stays within absolute bounds: Q at least q_floor, dihedral angles
//    within [angle_floor, max(angle_ceiling, the tet's maximum before)], element time step at
//    least dt_floor (the caller passes the mesh's minima: then no global minimum falls, and a
//    ceiling at most the mesh's maximum: then the maximum does not rise).
// Connectivity never changes; corners, locked and pinned vertices never move (the roles of
// `model`; an interior vertex moves when its vclass.dim is 3). Serial, in a fixed order.
#pragma once

#include "core/boundary/pattern_move.h"
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct NodalRaiseOptions {
  double target = 0;  // the nodal steps below this are raised (0: nothing to do)
  // The bounds every tet of a mover's star keeps (above); a tet's maximum dihedral angle's bound
  // is max(angle_ceiling, its maximum before the move).
  double q_floor = 0, angle_floor = 0, angle_ceiling = 180, dt_floor = 0;
  int max_vertices = 64;  // low vertices tried at most per pass (the lowest first)
  int passes = 3;         // passes over the low vertices (stops when nothing moves)
  // Each mover's search (pattern_move.h): the Hausdorff bound, the volume budget, its steps and
  // evaluations; its stop_at and extra_directions are set here (the target, the gradient's).
  PatternMoveOptions search;
  // Where none of the fixed directions of an interior mover rises, the directions of the star
  // value's gradient, with its components against the bounds nearly reached taken out (the star
  // on its bounds, the way up a narrow cone between the fixed directions).
  bool gradient_directions = false;
};

struct NodalRaiseStats {
  long nb_low = 0;                       // vertices below the target at the start
  long nb_moved = 0;                     // moves kept
  double min_before = 0, min_after = 0;  // the smallest nodal step of the mesh
};

// Dead tets (tets[4t] < 0) are ignored; mesh.adj is not needed. model without geometry: only
// interior vertices move.
NodalRaiseStats raise_nodal_steps(TetMesh& mesh, const BoundaryModel& model,
                                  const NodalRaiseOptions& options = {});

}  // namespace cvtmesh
