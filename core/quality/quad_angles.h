// The interior angles of a planar quadrangle, in degrees: the smallest and the largest of its 4
// corners (90 and 90 for a rectangle). A corner is measured from its outgoing to its incoming
// edge counter-clockwise, so a reflex corner of a counter-clockwise quadrangle is above 180.
// Pure function of the coordinates.
#pragma once

namespace cvtmesh {

struct QuadAngles {
  double min = 0, max = 0;
};

// a, b, c, d: the 4 corners in order (2 doubles each), counter-clockwise.
QuadAngles quad_angles(const double* a, const double* b, const double* c, const double* d);

}  // namespace cvtmesh
