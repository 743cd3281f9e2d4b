#include "core/geometry/z_range.h"

#include <algorithm>
#include <cmath>

namespace cvtmesh {

ZRange z_range(const std::vector<double>& xyz, const std::vector<int>* ids) {
  const long nv = static_cast<long>(xyz.size() / 3);
  double zmin = 1e300, zmax = -1e300, extent = 0;
  auto add = [&](long v) {
    zmin = std::min(zmin, xyz[3 * v + 2]);
    zmax = std::max(zmax, xyz[3 * v + 2]);
    extent = std::max({extent, std::fabs(xyz[3 * v]), std::fabs(xyz[3 * v + 1])});
  };
  if (ids) {
    for (int v : *ids)
      if (v >= 0 && v < nv) add(v);
  } else {
    for (long v = 0; v < nv; ++v) add(v);
  }
  ZRange r;
  if (zmin > zmax) return r;  // no point
  r.zmin = zmin;
  r.zmax = zmax;
  r.planar = zmax - zmin <= 1e-10 * std::max(1.0, extent);
  return r;
}

}  // namespace cvtmesh
