// One boundary vertex move, in two steps (check, then apply; the caller decides whether to keep
// it — an energy, a quality objective — as for the swaps' plan/apply/accept):
//  - plan_boundary_move projects a wanted position onto the vertex's own entity (its surface
//    patch or curve of the reference geometry; corners, locked and interior vertices do not move
//    here) and checks the result: every tet of its star stays positively oriented (exact
//    orient3d), the surface does not fold (surface_folds.h) and every triangle of its boundary
//    fan stays within `hausdorff` of the reference boundary (at its centroid and edge midpoints);
//  - apply_boundary_move writes the planned position.
#pragma once
#include "core/boundary/boundary_fans.h"
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {

enum class BoundaryMoveStatus {
  kOk = 0,
  kNotMovable,    // interior, corner, locked or periodic vertex
  kNoProjection,  // the reference geometry could not project the point
  kInverted,      // a tet of the star would be inverted or flat
  kTooFar,        // a fan triangle would leave the Hausdorff tolerance
  kFolds,         // the fan would fold the surface (surface_folds.h)
};

struct PlannedBoundaryMove {
  BoundaryMoveStatus status = BoundaryMoveStatus::kNotMovable;
  double position[3] = {0, 0, 0};  // on the vertex's entity (valid when status == kOk)
};

// `star` and `fans` must be current for v (vertex_tets / boundary_fans of the mesh as it is).
// hausdorff: absolute distance; +inf skips that check. The mesh is not changed.
PlannedBoundaryMove plan_boundary_move(const TetMesh& mesh, const BoundaryModel& model,
                                       const VertexTets& star, const BoundaryFans& fans, int v,
                                       const double* wanted, double hausdorff);

// plan_boundary_move's checks only, for `position` already on v's entity (what project_on_entity
// gave for the wanted position; kNoProjection if not finite): the same plan as
// plan_boundary_move's. For callers that project many targets at once (in parallel: a projection
// reads only the geometry).
PlannedBoundaryMove check_boundary_move(const TetMesh& mesh, const BoundaryModel& model,
                                        const VertexTets& star, const BoundaryFans& fans, int v,
                                        const double* position, double hausdorff);

// Whether v's fan, with v at `position`, stays within `hausdorff` of the reference boundary: at
// each triangle's sample points (boundary_hausdorff.h: centroid, edge midpoints, (2/3,1/6,1/6));
// and the other way, every fan vertex's input position within `hausdorff` of its own fan
// (fan_covers_input).
bool fan_within_tolerance(const TetMesh& mesh, const BoundaryModel& model, const BoundaryFans& fans,
                          int v, const double* position, double hausdorff);

// Whether the input position of boundary vertex u is within `hausdorff` of u's fan, with v at
// `position` (v may be u or a neighbour).
bool fan_covers_input(const TetMesh& mesh, const BoundaryModel& model, const BoundaryFans& fans,
                      int u, int v, const double* position, double hausdorff);

void apply_boundary_move(TetMesh& mesh, int v, const PlannedBoundaryMove& move);

// Projects p onto v's entity (q, 3 doubles); false when v does not move on one.
bool project_on_entity(const BoundaryModel& model, int v, const double* p, double* q);

// The unit tangent (axis, 3 doubles) at p of curve vertex v's curve: of the projections of p
// moved by 0.1 len along each coordinate axis, the farthest from p, normalized. False when the
// projections do not move (the farthest within 1e-9 len of p) or v is on no curve.
bool curve_tangent(const BoundaryModel& model, int v, const double* p, double len, double* axis);

}  // namespace cvtmesh
