// The common ascent step of max-min smoothing (maxmin_ascent_step.h): every active function
// rises along the direction, which stays in the tangent space it is given.
#include "core/smoothing/maxmin_ascent_step.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cvtmesh {
namespace {

std::vector<std::pair<double, Vec3>> two_active() {
  // Two functions at the minimum 0.2 with gradients (1, 1, 1) and (-1, 1, 2), a third far above.
  return {{0.2, {1, 1, 1}}, {0.2, {-1, 1, 2}}, {0.9, {0, -5, 0}}};
}

TEST(MaxMinAscentStep, EveryActiveFunctionRisesAndTheStepIsBounded) {
  auto cand = two_active();
  const AscentStep s = maxmin_ascent_step(cand, 0.2, 0.1);
  ASSERT_TRUE(s.ok);
  const double slope = dot(s.direction, s.direction);
  EXPECT_GT(slope, 0);
  EXPECT_GE(dot(Vec3{1, 1, 1}, s.direction), slope - 1e-12);
  EXPECT_GE(dot(Vec3{-1, 1, 2}, s.direction), slope - 1e-12);
  EXPECT_LE(s.alpha * std::sqrt(slope), 0.1 + 1e-15);  // at most max_step
  // The third function falls along d: the step stops where it would meet the minimum.
  const double third = 0.9 + s.alpha * dot(Vec3{0, -5, 0}, s.direction);
  EXPECT_GE(third, 0.2 + s.alpha * slope - 1e-12);
}

TEST(MaxMinAscentStep, TheDirectionStaysInTheTangentSpace) {
  const Vec3 n{0, 0, 1};
  auto cand = two_active();
  TangentSpace plane;
  plane.kind = TangentSpace::kPlane;
  plane.axis = n;
  const AscentStep s = maxmin_ascent_step(cand, 0.2, 0.1, plane);
  ASSERT_TRUE(s.ok);
  EXPECT_NEAR(dot(s.direction, n), 0, 1e-15);
  auto cand2 = two_active();
  TangentSpace line;
  line.kind = TangentSpace::kLine;
  line.axis = Vec3{1, 0, 0};
  const AscentStep l = maxmin_ascent_step(cand2, 0.2, 0.1, line);
  // Along x the two active gradients disagree (+1, -1): no common ascent.
  EXPECT_FALSE(l.ok);
}

TEST(MaxMinAscentStep, OpposedGradientsHaveNoAscent) {
  std::vector<std::pair<double, Vec3>> cand = {{0.3, {1, 0, 0}}, {0.3, {-1, 0, 0}}};
  EXPECT_FALSE(maxmin_ascent_step(cand, 0.3, 1).ok);
}

}  // namespace
}  // namespace cvtmesh
