#include "core/swap/polygon_triangulations.h"

#include <stdexcept>
#include <string>

namespace cvtmesh {
namespace {

constexpr int kMinN = 3, kMaxN = 7;

// Triangulations of the sub-polygon v[lo..hi] (vertex ids in increasing order), as lists of
// triangles. The edge (v[lo], v[hi]) lies in exactly one triangle (v[lo], v[m], v[hi]).
std::vector<std::vector<std::array<int, 3>>> triangulate(int lo, int hi) {
  std::vector<std::vector<std::array<int, 3>>> out;
  if (hi - lo < 2) {
    out.emplace_back();
    return out;
  }
  for (int m = lo + 1; m < hi; ++m) {
    const auto left = triangulate(lo, m), right = triangulate(m, hi);
    for (const auto& a : left)
      for (const auto& b : right) {
        std::vector<std::array<int, 3>> t = a;
        t.insert(t.end(), b.begin(), b.end());
        t.push_back({lo, m, hi});
        out.push_back(std::move(t));
      }
  }
  return out;
}

PolygonTriangulations build(int n) {
  PolygonTriangulations p;
  p.n = n;
  std::vector<std::vector<std::vector<int>>> index(
      n, std::vector<std::vector<int>>(n, std::vector<int>(n, -1)));
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      for (int c = b + 1; c < n; ++c) {
        index[a][b][c] = static_cast<int>(p.triangles.size());
        p.triangles.push_back({a, b, c});
      }
  for (const auto& tr : triangulate(0, n - 1)) {
    std::vector<int> ids;
    for (const auto& t : tr) ids.push_back(index[t[0]][t[1]][t[2]]);
    p.triangulations.push_back(std::move(ids));
  }
  return p;
}

}  // namespace

const PolygonTriangulations& polygon_triangulations(int n) {
  static const std::vector<PolygonTriangulations> tables = [] {
    std::vector<PolygonTriangulations> t;
    for (int k = kMinN; k <= kMaxN; ++k) t.push_back(build(k));
    return t;
  }();
  if (n < kMinN || n > kMaxN)
    throw std::invalid_argument("polygon_triangulations: n = " + std::to_string(n) +
                                " is outside 3..7");
  return tables[n - kMinN];
}

}  // namespace cvtmesh
