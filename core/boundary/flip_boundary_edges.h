// Surface edge flips (issue 13, item 3): the edge (a, b) between two boundary triangles (a, b, c)
// and (a, b, d) of one surface entity, both nearly coplanar (their normals within flat_angle), is
// replaced by (c, d): the k tets around (a, b) (one region, an open ring from c to d, k <= 6) are
// replaced by the 2(k-1) tets that cone the best triangulation of the polygon (c, r1, ..., d)
// to a and to b (the triangles (a, c, d) and (b, c, d) become the boundary, with the surface tag of
// the old ones). Checked, then applied:
//  - refused when (a, b) may be a curve (BoundaryModel::may_be_curve_edge), when (c, d) is
//    already an edge of the mesh, when a new tet is not positively oriented (exact orient3d), when
//    a new triangle leaves the Hausdorff tolerance, when the volume change (the tet abcd's) does
//    not fit the volume budget;
//  - kept only if the minimum over the new tets' min(Q, min dihedral / 60 degrees) and the new
//    triangles' Q rises by at least min_gain above the old one.
// Vertices never move. On exit the tets are compacted and the adjacency current (repaired in
// place).
#pragma once
#include <limits>

#include "core/geometry/boundary_geometry.h"
#include "core/boundary/volume_budget.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct BoundaryFlipOptions {
  double flat_angle = 15;  // degrees between the two triangles' normals, at most
  double tri_below = 0.6;  // try the edges of the boundary triangles with Q below this
  double min_gain = 1e-3;
  int passes = 3;
  double hausdorff = std::numeric_limits<double>::infinity();  // absolute
  VolumeBudget* volume_budget = nullptr;
};

struct BoundaryFlipStats {
  int passes = 0;
  long nb_tried = 0, nb_flipped = 0;
};

BoundaryFlipStats flip_boundary_edges(TetMesh& mesh, const BoundaryModel& model,
                                      const BoundaryFlipOptions& options = {});

}  // namespace cvtmesh
