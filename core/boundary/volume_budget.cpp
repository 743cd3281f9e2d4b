#include "core/boundary/volume_budget.h"

#include <cmath>

#include "core/geometry/tet_geometry.h"
#include "core/pipeline/verify_mesh.h"

namespace cvtmesh {

VolumeBudget VolumeBudget::of(const TetMesh& mesh, double tolerance) {
  VolumeBudget b;
  b.tolerance = tolerance;
  for (const auto& [r, v] : region_volumes(mesh)) {
    b.region.push_back(r);
    b.volume.push_back(v);
    b.change.push_back(0);
  }
  return b;
}

bool VolumeBudget::admits(const TetMesh& m, const VertexTets& star, int v, const double* q,
                          std::vector<double>& delta) const {
  delta.assign(region.size(), 0);
  if (!std::isfinite(tolerance)) return true;
  for (const int* t = star.begin_of(v); t != star.end_of(v); ++t) {
    const int* w = &m.tets[4 * static_cast<std::size_t>(*t)];
    const double* p[4];
    const double* p_new[4];
    for (int k = 0; k < 4; ++k) {
      p[k] = m.point(w[k]);
      p_new[k] = w[k] == v ? q : p[k];
    }
    const double d = tet_volume(p_new[0], p_new[1], p_new[2], p_new[3]) -
                     tet_volume(p[0], p[1], p[2], p[3]);
    for (std::size_t i = 0; i < region.size(); ++i)
      if (region[i] == m.tet_region[*t]) delta[i] += d;
  }
  for (std::size_t i = 0; i < region.size(); ++i)
    if (std::fabs(change[i] + delta[i]) > tolerance * std::fabs(volume[i])) return false;
  return true;
}

void VolumeBudget::commit(const std::vector<double>& delta) {
  for (std::size_t i = 0; i < change.size() && i < delta.size(); ++i) change[i] += delta[i];
}

}  // namespace cvtmesh
