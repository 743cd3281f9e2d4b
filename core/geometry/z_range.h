// Is a point set planar in z? The range of z over the points (all, or the listed ids) and the
// decision shared by every reader of 2D meshes: z varies by at most 1e-10 of the x/y extent.
#pragma once
#include <vector>

namespace cvtmesh {

struct ZRange {
  double zmin = 0, zmax = 0;
  bool planar = true;  // zmax - zmin <= 1e-10 * max(1, |x|, |y|)
};

// xyz: #V by 3. ids: vertices to consider (ids out of range are skipped); null = all of them.
ZRange z_range(const std::vector<double>& xyz, const std::vector<int>* ids = nullptr);

}  // namespace cvtmesh
