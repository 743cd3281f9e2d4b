#include "core/mesh/find_surface_intersections.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

namespace cvtmesh {
namespace {

// Random small triangles in the unit cube, more than one chunk of the parallel search (4096), with
// shared vertices (every third triangle reuses the previous one's last two vertices): many
// crossings, and pairs sharing an edge or a vertex.
void random_soup(int nf, std::vector<double>& xyz, std::vector<int>& tris) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1), e(-0.02, 0.02);
  for (int f = 0; f < nf; ++f) {
    const double c[3] = {u(rng), u(rng), u(rng)};
    const int first = static_cast<int>(xyz.size() / 3);
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) xyz.push_back(c[d] + e(rng));
    if (f % 3 == 2) {
      tris.insert(tris.end(), {tris[tris.size() - 2], tris[tris.size() - 1], first});
    } else {
      tris.insert(tris.end(), {first, first + 1, first + 2});
    }
  }
}

TEST(FindSurfaceIntersections, SamePairsForAnyThreadCountAndAPrefixOfAllPairs) {
  std::vector<double> xyz;
  std::vector<int> tris;
  random_soup(6000, xyz, tris);
  const int was = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto all = find_surface_intersections(xyz, tris, 1 << 30);
  ASSERT_GT(all.size(), 200u);
  ASSERT_GT(all.back()[0], 4096);  // pairs past the first chunk of the parallel search
  ASSERT_TRUE(std::is_sorted(all.begin(), all.end()));
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    EXPECT_EQ(find_surface_intersections(xyz, tris, 1 << 30), all) << threads;
    // The search stopped at max_pairs: the first max_pairs of all the pairs (sorted).
    for (int m : {1, static_cast<int>(all.size() * 4 / 5)}) {
      const std::vector<std::array<int, 2>> prefix(all.begin(), all.begin() + m);
      EXPECT_EQ(find_surface_intersections(xyz, tris, m), prefix) << threads << " " << m;
    }
  }
  omp_set_num_threads(was);
}

}  // namespace
}  // namespace cvtmesh
