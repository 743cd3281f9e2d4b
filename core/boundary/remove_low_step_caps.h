// Removal of the cap vertices whose nodal time step is low (issue 17: the global explicit time
// step of the result never below the input's). A cap vertex (collapse_boundary_edges.h,
// is_cap_vertex) is a surface vertex of valence 3 standing on a single tet: its nodal step
// (vertex_time_step.h) is that tet's height over its fourth face, which no move of the vertex
// within the mesh's extremes raises far when the tet is flat (igl_cheburashka's lowest after the
// free boundary). Removing it (the collapse of collapse_boundary_edges.h with cap_vertices: its
// link condition, Hausdorff bound, volume budget, new triangle's quality and turn) leaves the
// fourth face as the surface triangle; the tet goes, no other tet changes, so no quality row of
// the tets gets worse.
//
// For each cap vertex below `target`, lowest first: the collapse is kept only if each of the
// tet's three other vertices keeps min(nodal step, target) (it loses the tet's terms, which can
// lower it where the tet was its best).
#pragma once
#include <limits>

#include "core/boundary/volume_budget.h"
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct LowCapOptions {
  double target = 0;       // the cap vertices whose nodal step is below this go (0: none)
  double flat_angle = 40;  // degrees the triangle left may turn from the one it replaces
  double hausdorff = std::numeric_limits<double>::infinity();  // absolute
  VolumeBudget* volume_budget = nullptr;
};

struct LowCapStats {
  long nb_caps = 0, nb_removed = 0;  // cap vertices below the target; those removed
};

// mesh.adj is built if it is not. The removed vertices stay in the arrays, in no element, fixed in
// model (as the coarsening leaves them; the pipeline drops them). On exit the dead tets and
// triangles are compacted and the adjacency is valid.
LowCapStats remove_low_step_caps(TetMesh& mesh, BoundaryModel& model,
                                 const LowCapOptions& options = {});

}  // namespace cvtmesh
