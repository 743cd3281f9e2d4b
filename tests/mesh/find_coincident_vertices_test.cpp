// Pairs of vertices closer than the tolerance (core/mesh/find_coincident_vertices.h): the same
// pairs as a comparison of every pair, for clusters of near-duplicates placed across the grid's
// cell sides as well as inside cells, unused vertices left out, at most max_pairs (the smallest).
#include "core/mesh/find_coincident_vertices.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace cvtmesh {
namespace {

std::vector<std::array<int, 2>> every_pair(const std::vector<double>& xyz,
                                           const std::vector<char>& used, double tol) {
  std::vector<std::array<int, 2>> pairs;
  const int nv = static_cast<int>(xyz.size() / 3);
  for (int v = 0; v < nv; ++v)
    for (int w = v + 1; w < nv; ++w) {
      if (!used.empty() && (!used[v] || !used[w])) continue;
      double d2 = 0;
      for (int d = 0; d < 3; ++d)
        d2 += (xyz[3 * v + d] - xyz[3 * w + d]) * (xyz[3 * v + d] - xyz[3 * w + d]);
      if (d2 <= tol * tol) pairs.push_back({v, w});
    }
  return pairs;
}

TEST(FindCoincidentVertices, TheSamePairsAsComparingEveryPair) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0, 1), sign(-1, 1);
  const double rel = 1e-4;  // the unit cube's diagonal is sqrt(3): tol ~1.7e-4
  const double tol = rel * std::sqrt(3.0);
  std::vector<double> xyz = {0, 0, 0, 1, 1, 1};  // the bounding box
  for (int i = 0; i < 600; ++i) {
    double p[3];
    for (double& x : p) x = unit(rng);
    // A third of the clusters straddle a grid line (cells of side 2 tol from 0).
    if (i % 3 == 0) p[i % 9 / 3] = std::round(p[i % 9 / 3] / (2 * tol)) * 2 * tol;
    const int n = 1 + i % 4;
    for (int k = 0; k < n; ++k)
      for (double x : p)
        xyz.push_back(std::min(1.0, std::max(0.0, x + 0.8 * tol * sign(rng) / std::sqrt(3.0))));
  }
  std::vector<char> used(xyz.size() / 3, 1);
  for (std::size_t v = 7; v < used.size(); v += 11) used[v] = 0;
  for (const bool with_used : {false, true}) {
    const std::vector<char> u = with_used ? used : std::vector<char>{};
    const auto expected = every_pair(xyz, u, tol);
    ASSERT_GT(expected.size(), 300u);
    EXPECT_EQ(find_coincident_vertices(xyz, u, rel, 1 << 20), expected);
    // At most max_pairs: the smallest ones.
    const auto some = find_coincident_vertices(xyz, u, rel, 50);
    ASSERT_EQ(some.size(), 50u);
    EXPECT_TRUE(std::equal(some.begin(), some.end(), expected.begin()));
  }
}

TEST(FindCoincidentVertices, ExactDuplicatesOnlyAtZeroTolerance) {
  const std::vector<double> xyz = {0,   0,   0,   1,           1,   1,   0.5, 0.5,
                                   0.5, 0.5, 0.5, 0.5 + 1e-15, 0.5, 0.5, 0.5};
  const auto pairs = find_coincident_vertices(xyz, {}, 0);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0], (std::array<int, 2>{2, 4}));
}

}  // namespace
}  // namespace cvtmesh
