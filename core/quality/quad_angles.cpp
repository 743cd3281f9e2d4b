#include "core/quality/quad_angles.h"

#include <algorithm>
#include <cmath>

namespace cvtmesh {

QuadAngles quad_angles(const double* a, const double* b, const double* c, const double* d) {
  const double* p[4] = {a, b, c, d};
  QuadAngles r{360, 0};
  for (int k = 0; k < 4; ++k) {
    const double* o = p[k];
    const double* n = p[(k + 1) % 4];
    const double* m = p[(k + 3) % 4];
    const double ux = n[0] - o[0], uy = n[1] - o[1];  // outgoing
    const double vx = m[0] - o[0], vy = m[1] - o[1];  // back along the incoming edge
    double deg = std::atan2(ux * vy - uy * vx, ux * vx + uy * vy) * 180 / M_PI;
    if (deg < 0) deg += 360;
    r.min = std::min(r.min, deg);
    r.max = std::max(r.max, deg);
  }
  return r;
}

}  // namespace cvtmesh
