// The scaled Jacobian of a planar quadrangle: the minimum over its 4 corners of the cross product
// of the unit vectors along the corner's two edges (next edge x previous edge, so positive at a
// convex corner of a counter-clockwise quadrangle). 1 for a rectangle; in (0, 1] for a strictly
// convex counter-clockwise quadrangle; <= 0 where a corner is reflex, flat, or the quadrangle is
// clockwise or folded. Pure function of the coordinates (Knupp's measure; Gmsh's "SICN" of a
// linear quad, Verdict's quad scaled Jacobian).
#pragma once

namespace cvtmesh {

// a, b, c, d: the 4 corners in order (2 doubles each). 0 when an edge has zero length.
double quad_scaled_jacobian(const double* a, const double* b, const double* c, const double* d);

}  // namespace cvtmesh
