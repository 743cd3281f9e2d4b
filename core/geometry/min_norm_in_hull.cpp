#include "core/geometry/min_norm_in_hull.h"

#include <algorithm>
#include <limits>

namespace cvtmesh {

Vec3 min_norm_in_hull(const std::vector<Vec3>& g) {
  const int n = static_cast<int>(g.size());
  double scale = 0;
  for (const Vec3& x : g) scale = std::max(scale, norm2(x));
  const double tol = 1e-12 * scale;
  auto optimal = [&](const Vec3& x) {
    const double xx = norm2(x);
    for (const Vec3& y : g)
      if (dot(y, x) < xx - tol) return false;
    return true;
  };
  Vec3 best{0, 0, 0};
  double best_n = std::numeric_limits<double>::infinity();
  auto offer = [&](const Vec3& x) {
    const double xx = norm2(x);
    if (xx < best_n && optimal(x)) {
      best = x;
      best_n = xx;
    }
  };
  for (int i = 0; i < n; ++i) offer(g[i]);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const Vec3 e = g[j] - g[i];
      const double ee = norm2(e);
      if (ee <= tol) continue;
      const double s = -dot(g[i], e) / ee;
      if (s > 0 && s < 1) offer(g[i] + s * e);
    }
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        // x = g_i + s (g_j - g_i) + r (g_k - g_i), orthogonal to both differences.
        const Vec3 u = g[j] - g[i], w = g[k] - g[i];
        const double uu = dot(u, u), uw = dot(u, w), ww = dot(w, w);
        const double det = uu * ww - uw * uw;
        if (det <= 1e-14 * uu * ww || det <= 0) continue;
        const double bu = -dot(g[i], u), bw = -dot(g[i], w);
        const double s = (bu * ww - bw * uw) / det, r = (bw * uu - bu * uw) / det;
        if (s > 0 && r > 0 && s + r < 1) offer(g[i] + s * u + r * w);
      }
  if (best_n == std::numeric_limits<double>::infinity() || best_n <= tol) return {0, 0, 0};
  return best;
}

}  // namespace cvtmesh
