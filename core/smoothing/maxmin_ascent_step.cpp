#include "core/smoothing/maxmin_ascent_step.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/min_norm_in_hull.h"

namespace cvtmesh {

AscentStep maxmin_ascent_step(std::vector<std::pair<double, Vec3>>& cand, double fmin,
                              double max_step, const TangentSpace& space) {
  AscentStep s;
  if (space.kind != TangentSpace::kFree)
    for (auto& c : cand) c.second = space.project(c.second);
  // The active set: the candidates within a small band of the minimum (at most 8).
  const double band = 1e-3 + 1e-2 * std::fabs(fmin);
  std::vector<std::pair<double, int>> order;
  for (int k = 0; k < static_cast<int>(cand.size()); ++k)
    if (cand[k].first <= fmin + band) order.push_back({cand[k].first, k});
  std::sort(order.begin(), order.end());
  if (order.size() > 8) order.resize(8);
  std::vector<Vec3> active;
  for (const auto& a : order) active.push_back(cand[a.second].second);
  if (active.empty()) return s;
  const Vec3 d = min_norm_in_hull(active);
  const double slope = norm2(d);
  if (!(slope > 0)) return s;
  // Step length: where the linearised minimum meets another candidate's linearisation.
  double alpha = max_step / std::sqrt(slope);
  for (const auto& [value, grad] : cand) {
    const double sj = dot(grad, d);
    if (sj < slope && value > fmin + band) alpha = std::min(alpha, (value - fmin) / (slope - sj));
  }
  s.direction = d;
  s.alpha = alpha;
  s.ok = true;
  return s;
}

}  // namespace cvtmesh
