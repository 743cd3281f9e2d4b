#include "core/mesh/find_coincident_vertices.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace cvtmesh {

std::vector<std::array<int, 2>> find_coincident_vertices(const std::vector<double>& xyz,
                                                         const std::vector<char>& used,
                                                         double relative_tolerance, int max_pairs) {
  std::vector<std::array<int, 2>> pairs;
  const int nv = static_cast<int>(xyz.size() / 3);
  auto is_used = [&](int v) { return used.empty() || used[v]; };
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (int v = 0; v < nv; ++v)
    if (is_used(v))
      for (int d = 0; d < 3; ++d) {
        lo[d] = std::min(lo[d], xyz[3 * v + d]);
        hi[d] = std::max(hi[d], xyz[3 * v + d]);
      }
  if (!(lo[0] <= hi[0])) return pairs;
  const double diag =
      std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                (hi[2] - lo[2]) * (hi[2] - lo[2]));
  const double tol = relative_tolerance * diag;
  // Grid of cells of side > tol (at least 2*tol): a close pair lies in the same or adjacent cells.
  const double cell = std::max(2 * tol, diag * 1e-6) + 1e-300;
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return static_cast<std::uint64_t>(i * 73856093) ^ static_cast<std::uint64_t>(j * 19349663) ^
           static_cast<std::uint64_t>(k * 83492791);
  };
  std::unordered_multimap<std::uint64_t, int> grid;
  grid.reserve(static_cast<std::size_t>(nv));
  auto coord = [&](int v, int d) {
    return static_cast<std::int64_t>(std::floor((xyz[3 * v + d] - lo[d]) / cell));
  };
  for (int v = 0; v < nv; ++v)
    if (is_used(v)) grid.emplace(key(coord(v, 0), coord(v, 1), coord(v, 2)), v);
  const double tol2 = tol * tol;
  for (int v = 0; v < nv && static_cast<int>(pairs.size()) < max_pairs; ++v) {
    if (!is_used(v)) continue;
    const std::int64_t c[3] = {coord(v, 0), coord(v, 1), coord(v, 2)};
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj)
        for (int dk = -1; dk <= 1; ++dk) {
          auto range = grid.equal_range(key(c[0] + di, c[1] + dj, c[2] + dk));
          for (auto it = range.first; it != range.second; ++it) {
            const int w = it->second;
            if (w <= v) continue;
            double d2 = 0;
            for (int d = 0; d < 3; ++d) {
              const double e = xyz[3 * v + d] - xyz[3 * w + d];
              d2 += e * e;
            }
            if (d2 <= tol2) pairs.push_back({v, w});
          }
        }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  if (static_cast<int>(pairs.size()) > max_pairs) pairs.resize(max_pairs);
  return pairs;
}

}  // namespace cvtmesh
