#include "core/boundary/triangle_set_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

// "Some triangle within r of p" (the Hausdorff checks of the boundary moves) agrees with the
// distance to the closest triangle: on the boundary of a cube minus a ball, points near and far,
// radii around their distance (a disagreement is allowed only within rounding of r).
TEST(TriangleSetDistance, AnyWithinAgreesWithTheDistance) {
  const MeshData d = testing::cube_sphere(0.2, 0.15);
  const TriangleSetDistance set(d.tet.xyz, d.tet.tris);
  ASSERT_FALSE(set.empty());
  unsigned state = 99;
  auto rnd = [&] {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / double(1 << 24);
  };
  int near = 0, checked = 0;
  for (int i = 0; i < 3000; ++i) {
    const double p[3] = {2.4 * rnd() - 1.2, 2.4 * rnd() - 1.2, 2.4 * rnd() - 1.2};
    const double dist = set.distance(p);
    for (double f : {0.0, 0.5, 0.999, 1.001, 2.0}) {
      const double r = f * dist + (f == 0 ? 1e-3 : 0);
      if (std::fabs(dist - r) <= 1e-12 * (1 + dist)) continue;
      ++checked;
      EXPECT_EQ(set.any_within(p, r), dist <= r) << "point " << i << " r/dist " << f;
    }
    near += dist < 0.05;
    EXPECT_TRUE(set.any_within(p, std::numeric_limits<double>::infinity()));
    EXPECT_FALSE(set.any_within(p, -1));
  }
  EXPECT_GT(near, 10);
  EXPECT_GT(checked, 10000);
}

}  // namespace
}  // namespace cvtmesh
