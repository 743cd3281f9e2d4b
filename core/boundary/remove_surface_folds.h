// Removal of surface folds (issue 17: igl_cheburashka's worst tet). A fold vertex is a surface
// or curve vertex of valence 3 one of whose three triangles is turned over against the other two
// (each turn above acos(kFoldFloor), about 154 degrees): an input defect. igl_cheburashka's vertex
// 2 lies 2e-5 from the plane of its three neighbours, its triangle (0, 1, 2) turning by 177 and
// 179 degrees against the others; the feature detection makes those edges curves, so no flip or
// collapse of the coarsening may touch it, and every tet standing on the triangle is flat (the
// model's worst, Q 0.0010). Removing the vertex (the collapse of
// core/boundary/collapse_boundary_edges.h with fold_vertices: its link condition, quality floors,
// Hausdorff bound and volume budget) leaves one triangle over its three neighbours; its curve
// edges go with it.
#pragma once
#include <limits>

#include "core/boundary/volume_budget.h"
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct FoldRemovalOptions {
  double flat_angle = 40;  // degrees the triangle left may turn from the one it was
  double hausdorff = std::numeric_limits<double>::infinity();  // absolute
  VolumeBudget* volume_budget = nullptr;
  int passes = 3;  // a fold whose neighbour's collapse came first in a pass waits for the next
};

struct FoldRemovalStats {
  long nb_folds = 0, nb_removed = 0;
};

// Each pass collapses every fold vertex (in vertex order, on the stars and fans of the pass's
// start, none next to another's collapse) onto the first of its three neighbours the check
// accepts; until a pass removes none. On exit the dead tets and triangles are compacted and the
// adjacency is valid.
FoldRemovalStats remove_surface_folds(TetMesh& mesh, BoundaryModel& model,
                                      const FoldRemovalOptions& options = {});

}  // namespace cvtmesh
