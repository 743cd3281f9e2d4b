// Edge flips of a surface mesh in space (a TetMesh without tets: core/mesh/check_surface_mesh.h):
// the edge (a, b) of exactly two triangles (a, b, c) and (a, b, d) of one surface entity, nearly
// coplanar, becomes (c, d) — the surface counterpart of flip_boundary_edges, with no tets around.
// Checked, then applied:
//  - refused when (a, b) may be a curve (BoundaryModel::may_be_curve_edge) or is one of
//    `kept_edges` (the file's line elements), when (c, d) is already an edge, when the two
//    triangles' normals are more than flat_angle apart (coplanar_only: when a, b, c, d are not
//    exactly coplanar, orient3d), when a new triangle turns over against the old pair (exact
//    orient3d against a point on the pair's normal) or the flip folds the surface around it
//    (surface_folds.h), when a new triangle leaves the Hausdorff tolerance (not checked for
//    coplanar_only: the surface is unchanged);
//  - kept only if the smaller minimum angle of the two triangles rises by more than min_gain
//    degrees (the Delaunay criterion where the pair is flat), their larger maximum angle does not
//    rise above max(its old value, max_angle_ceiling) and their smaller Q does not fall.
// Vertices never move; the new triangles keep the surface tags and element tags of the old ones
// and their turning sense.
#pragma once
#include <array>
#include <limits>
#include <vector>

#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct SurfaceFlipOptions {
  double flat_angle = 10;          // degrees between the two triangles' normals, at most
  bool coplanar_only = false;      // flip only where a, b, c, d are exactly coplanar
  double min_gain = 1e-6;          // degrees
  double max_angle_ceiling = 180;  // degrees
  int passes = 10;
  double hausdorff = std::numeric_limits<double>::infinity();  // absolute
  // Edges never flipped (smaller id first, sorted), e.g. the line elements of the file.
  std::vector<std::array<int, 2>> kept_edges;
};

struct SurfaceFlipStats {
  int passes = 0;
  long nb_tried = 0, nb_flipped = 0;
};

SurfaceFlipStats flip_surface_edges(TetMesh& mesh, const BoundaryModel& model,
                                    const SurfaceFlipOptions& options = {});

}  // namespace cvtmesh
