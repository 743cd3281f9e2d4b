#include "core/boundary/volume_budget.h"

#include <cmath>

#include "core/geometry/tet_geometry.h"
#include <map>

namespace cvtmesh {

std::vector<std::pair<int, double>> region_volumes_of(const TetMesh& m) {
  std::map<int, std::pair<double, double>> vol;  // Neumaier sum, compensation
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * static_cast<std::size_t>(t)];
    if (v[0] < 0) continue;
    const double x = tet_volume(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
    auto& [sum, c] = vol[m.tet_region[t]];
    const double s = sum + x;
    c += std::fabs(sum) >= std::fabs(x) ? (sum - s) + x : (x - s) + sum;
    sum = s;
  }
  std::vector<std::pair<int, double>> r;
  for (const auto& [region, s] : vol) r.push_back({region, s.first + s.second});
  return r;
}

VolumeBudget VolumeBudget::of(const TetMesh& mesh, double tolerance) {
  VolumeBudget b;
  b.tolerance = tolerance;
  for (const auto& [r, v] : region_volumes_of(mesh)) {
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
    const double d =
        tet_volume(p_new[0], p_new[1], p_new[2], p_new[3]) - tet_volume(p[0], p[1], p[2], p[3]);
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
