#include "core/mesh/find_coincident_vertices.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

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
  if (!(lo[0] <= hi[0]) || max_pairs <= 0) return pairs;
  const double diag =
      std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                (hi[2] - lo[2]) * (hi[2] - lo[2]));
  const double tol = relative_tolerance * diag;
  // Grid of cells of side > tol (at least 2*tol): a close pair lies in the same or adjacent cells,
  // and in an adjacent one along an axis only if the first point lies within tol of that side of
  // its cell (`reach`, in cell units, with a margin for the rounding of the cell coordinates:
  // a superset of the cells to look in, then the exact distance test).
  const double cell = std::max(2 * tol, diag * 1e-6) + 1e-300;
  const double reach = tol / cell + 1e-6;
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return static_cast<std::uint64_t>(i * 73856093) ^ static_cast<std::uint64_t>(j * 19349663) ^
           static_cast<std::uint64_t>(k * 83492791);
  };
  auto unit = [&](int v, int d) { return (xyz[3 * v + d] - lo[d]) / cell; };
  // The vertices by their cell's key (a sorted array, not a hash multimap: ~10x faster at 1.5M
  // vertices); cells sharing a key only add candidates.
  std::vector<std::pair<std::uint64_t, int>> grid;
  for (int v = 0; v < nv; ++v)
    if (is_used(v))
      grid.push_back({key(static_cast<std::int64_t>(std::floor(unit(v, 0))),
                          static_cast<std::int64_t>(std::floor(unit(v, 1))),
                          static_cast<std::int64_t>(std::floor(unit(v, 2)))),
                      v});
  std::sort(grid.begin(), grid.end());
  const double tol2 = tol * tol;
  // Each thread's vertices are a contiguous range in order, its pairs capped at max_pairs: the
  // max_pairs smallest of all the pairs are among them (the result does not depend on the
  // thread count).
#pragma omp parallel
  {
    std::vector<std::array<int, 2>> mine;
#pragma omp for schedule(static) nowait
    for (int v = 0; v < nv; ++v) {
      if (!is_used(v) || static_cast<int>(mine.size()) >= max_pairs) continue;
      std::int64_t c[3];
      int from[3], to[3];
      for (int d = 0; d < 3; ++d) {
        const double u = unit(v, d), f = std::floor(u);
        c[d] = static_cast<std::int64_t>(f);
        from[d] = u - f <= reach ? -1 : 0;
        to[d] = f + 1 - u <= reach ? 1 : 0;
      }
      for (int di = from[0]; di <= to[0]; ++di)
        for (int dj = from[1]; dj <= to[1]; ++dj)
          for (int dk = from[2]; dk <= to[2]; ++dk) {
            const std::uint64_t k = key(c[0] + di, c[1] + dj, c[2] + dk);
            auto it = std::lower_bound(grid.begin(), grid.end(), std::make_pair(k, v + 1));
            for (; it != grid.end() && it->first == k; ++it) {
              const int w = it->second;
              double d2 = 0;
              for (int d = 0; d < 3; ++d) {
                const double e = xyz[3 * v + d] - xyz[3 * w + d];
                d2 += e * e;
              }
              if (d2 <= tol2) mine.push_back({v, w});
            }
          }
    }
#pragma omp critical
    pairs.insert(pairs.end(), mine.begin(), mine.end());
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  if (static_cast<int>(pairs.size()) > max_pairs) pairs.resize(max_pairs);
  return pairs;
}

}  // namespace cvtmesh
