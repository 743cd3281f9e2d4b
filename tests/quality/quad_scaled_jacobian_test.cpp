// The quadrangle's scaled Jacobian and angles (quad_scaled_jacobian.h, quad_angles.h) on shapes
// whose values are known in closed form.
#include "core/quality/quad_scaled_jacobian.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/quality/quad_angles.h"

namespace cvtmesh {
namespace {

TEST(QuadScaledJacobian, RectangleIsOneAndARhombusIsTheSineOfItsAngle) {
  const double a[2] = {0, 0}, b[2] = {3, 0}, c[2] = {3, 1}, d[2] = {0, 1};
  EXPECT_DOUBLE_EQ(quad_scaled_jacobian(a, b, c, d), 1.0);
  const QuadAngles r = quad_angles(a, b, c, d);
  EXPECT_NEAR(r.min, 90, 1e-12);
  EXPECT_NEAR(r.max, 90, 1e-12);
  // A rhombus with angles 60 and 120 degrees: every corner's cross product is sin 60.
  const double s = std::sqrt(3.0) / 2;
  const double p[2] = {0, 0}, q[2] = {1, 0}, u[2] = {1.5, s}, w[2] = {0.5, s};
  EXPECT_NEAR(quad_scaled_jacobian(p, q, u, w), s, 1e-15);
  const QuadAngles ra = quad_angles(p, q, u, w);
  EXPECT_NEAR(ra.min, 60, 1e-12);
  EXPECT_NEAR(ra.max, 120, 1e-12);
}

TEST(QuadScaledJacobian, ClockwiseReflexAndDegenerateAreNotPositive) {
  const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {1, 1}, d[2] = {0, 1};
  EXPECT_DOUBLE_EQ(quad_scaled_jacobian(a, d, c, b), -1.0);  // clockwise
  // A dart: the corner at (0.2, 0.2) is reflex (sin of 270 degrees).
  const double r[2] = {0.2, 0.2};
  EXPECT_LT(quad_scaled_jacobian(a, b, r, d), 0);
  EXPECT_GT(quad_angles(a, b, r, d).max, 180);
  // A repeated corner (zero-length edge).
  EXPECT_EQ(quad_scaled_jacobian(a, b, b, d), 0.0);
}

}  // namespace
}  // namespace cvtmesh
