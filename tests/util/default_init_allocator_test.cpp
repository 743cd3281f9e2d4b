#include "core/util/default_init_allocator.h"

#include <gtest/gtest.h>

#include <vector>

namespace cvtmesh {
namespace {

// CellMesh::dual_piece relies on a vector with this allocator behaving as a vector: values
// written survive growth (reserve, resize past the capacity), resize(n, x) and assign still fill,
// and resize() within the capacity keeps what was written.
TEST(DefaultInitAllocator, WrittenValuesSurviveGrowthAndExplicitFillsStillFill) {
  std::vector<double, DefaultInitAllocator<double>> v;
  v.resize(1000);
  for (int i = 0; i < 1000; ++i) v[i] = 0.5 * i;
  v.reserve(5000);
  v.resize(3000);
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(v[i], 0.5 * i) << i;
  v.resize(100000);  // past the capacity: reallocates, moving the old contents
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(v[i], 0.5 * i) << i;
  v.resize(10);
  v.resize(20, 7.0);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(v[i], 0.5 * i) << i;
  for (int i = 10; i < 20; ++i) EXPECT_EQ(v[i], 7.0) << i;
  v.assign(50, -1.0);
  for (double x : v) EXPECT_EQ(x, -1.0);
  v.push_back(3.0);
  EXPECT_EQ(v.back(), 3.0);
  EXPECT_EQ(v.size(), 51u);
}

}  // namespace
}  // namespace cvtmesh
