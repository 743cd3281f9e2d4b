// The two-sided Hausdorff distance between a mesh's boundary triangles and the reference
// boundary, on samples: each triangle's vertices, centroid, edge midpoints and the three points
// (2/3, 1/6, 1/6) (new -> reference), and the reference's own samples (reference -> new, against
// the new triangles by a CGAL AABB tree).
#pragma once
#include "core/boundary/boundary_fans.h"
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

// The Hausdorff bound, locally, for the flip of surface edge (a, b) to (c, d) (the triangles f1 and
// f2 of a, b's fans become (a, c, d) and (b, c, d)): the new triangles' samples are within
// `tolerance` of the reference, and the input position of each of a, b, c, d (model.input_xyz)
// is within it of its new fan. True if both hold (always with an infinite tolerance).
bool surface_flip_within(const TetMesh& mesh, const BoundaryModel& model, const BoundaryFans& fans,
                         int f1, int f2, int a, int b, int c, int d, double tolerance);

}  // namespace cvtmesh
