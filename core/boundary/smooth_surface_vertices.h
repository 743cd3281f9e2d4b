// One Gauss-Seidel pass of vertex moves over a surface mesh in space (a TetMesh without tets:
// core/mesh/check_surface_mesh.h), each vertex on its own entity of the reference geometry
// (surface patch or curve: BoundaryModel roles; corners and pinned vertices stay). Two moves:
//  - kCentroid: the constrained CVT step (Du, Gunzburger & Ju): the vertex towards the centroid of
//    its Voronoi region restricted to its fan (per fan triangle the points nearer to it than to
//    the two other corners: the triangle clipped by the two bisector planes — vertex, edge
//    midpoints, circumcentre, or less for an obtuse triangle; density uniform or from the input's
//    local size), by `relaxation`, then projected;
//  - kMaxMin: the vertex towards the positions that make each fan triangle isosceles on its
//    opposite edge with 60-degree base angles (angle-based smoothing) and towards the average of
//    its neighbours, by steps 1, 1/2, 1/4, the best kept only if the fan's minimum angle rises.
// Each move is checked (plan_boundary_move: projection, no fold of the surface, within the
// Hausdorff tolerance of the reference), no fan triangle may turn over (exact orient3d against a
// point on its old normal), and the fan's worst triangle may not end below min(its old worst,
// q_floor) in Q and min(old, angle_floor) in minimum angle, nor its maximum angle above
// max(old, angle_ceiling).
#pragma once
#include <limits>
#include <vector>

#include "core/boundary/boundary_fans.h"
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

enum class SurfaceMoveKind { kCentroid, kMaxMin };

struct SurfaceMoveOptions {
  SurfaceMoveKind kind = SurfaceMoveKind::kCentroid;
  double relaxation = 1.0;  // kCentroid: the fraction of the way to the centroid
  // kCentroid: #V local sizes (the input's mean edge length at each vertex); a fan triangle's
  // density is 1 / h^4 with h the mean of its corners' sizes (a graded mesh keeps its grading:
  // 2D CVT cells scale as density^(-1/4)). Null: uniform density.
  const std::vector<double>* sizes = nullptr;
  double hausdorff = std::numeric_limits<double>::infinity();  // absolute
  double q_floor = 0.6;        // a fan's worst Q may fall, but not below this (nor its old worst)
  double angle_floor = 30;     // the same for its minimum angle, degrees
  double angle_ceiling = 120;  // its maximum angle may rise, but not above this (nor its old)
};

struct SurfaceMoveStats {
  long nb_tried = 0, nb_moved = 0;
  double max_step = 0;  // the longest accepted move
};

// `fans` current for the mesh (boundary_fans); `vertices` in the order they are visited.
SurfaceMoveStats smooth_surface_vertices(TetMesh& mesh, const BoundaryModel& model,
                                         const BoundaryFans& fans, const std::vector<int>& vertices,
                                         const SurfaceMoveOptions& options = {});

// The minimum angle (degrees) and the minimum Q of v's fan triangles with v at `position`.
struct FanQuality {
  double min_angle = 180, q_min = 1, max_angle = 0;
};
FanQuality fan_quality(const TetMesh& mesh, const BoundaryFans& fans, int v,
                       const double* position);

}  // namespace cvtmesh
