// Validity of an order-2 (10-node) tetrahedron: is its map from the reference tet orientation
// preserving, as far as two checks see (a curved tet can fail only between the points they test)?
#pragma once

namespace cvtmesh {

// The mid-edge nodes' order: m[k] is on the edge (kTet10Edge[k][0], kTet10Edge[k][1]).
extern const int kTet10Edge[6][2];  // {0,1}, {0,2}, {0,3}, {1,2}, {1,3}, {2,3}

// c: the 4 corners (3 doubles each), positively oriented (orient3d(c0,c1,c2,c3) > 0 when the tet
// is straight); m: the 6 mid-edge nodes in kTet10Edge order. True if (1) the 8 straight sub-tets
// of the node lattice (4 at the corners, 4 in the octahedron, split along m02-m13) are all
// positive by the exact orient3d, and (2) the Jacobian determinant of the quadratic map is
// positive at the 10 nodes and at the centroid (floating point). A straight tet10 (midpoints
// exact) passes iff its corner tet is positive.
bool tet10_positive(const double* const c[4], const double* const m[6]);

}  // namespace cvtmesh
