// The two-sided Hausdorff distance between a mesh's boundary triangles and the reference
// boundary, on samples: each triangle's vertices, centroid, edge midpoints and the three points
// (2/3, 1/6, 1/6) (new -> reference), and the reference's own samples (reference -> new, against
// the new triangles by a CGAL AABB tree).
#pragma once
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct HausdorffDistance {
  double to_reference = 0;  // max over the new boundary's samples of the distance to the reference
  double from_reference =
      0;  // max over the reference's samples of the distance to the new boundary
  double value() const { return to_reference > from_reference ? to_reference : from_reference; }
};

HausdorffDistance boundary_hausdorff(const TetMesh& mesh, const BoundaryGeometry& reference);

// The sample points of triangle (a, b, c) used on the new side (10 points, 3 doubles each).
void triangle_samples(const double* a, const double* b, const double* c, double out[10][3]);

}  // namespace cvtmesh
