// Validity of an order-2 (6-node) triangle in the plane: is its map from the reference triangle
// orientation preserving everywhere on the triangle?
#pragma once

namespace cvtmesh {

// The mid-edge nodes' order (Gmsh's tri6): m[k] is on the edge (kTri6Edge[k][0], kTri6Edge[k][1]).
extern const int kTri6Edge[3][2];  // {0,1}, {1,2}, {2,0}

// c: the 3 corners, counter-clockwise (orient2d(c0,c1,c2) > 0 when the triangle is straight);
// m: the 3 mid-edge nodes in kTri6Edge order; only the first two doubles (x, y) of each are read.
// True if (1) the 4 straight sub-triangles of the node lattice (3 at the corners, 1 in the middle)
// are all positive by the exact orient2d, and (2) the Jacobian determinant of the quadratic map,
// a quadratic polynomial on the triangle, is positive at the 6 nodes, the centroid and at its
// minimum over the triangle (found in closed form: a corner, the critical point of an edge or of
// the interior; floating point). A straight tri6 (every m exactly 0.5 * (a + b)) passes iff its
// corner triangle is positive (exact orient2d).
bool tri6_positive(const double* const c[3], const double* const m[3]);

}  // namespace cvtmesh
