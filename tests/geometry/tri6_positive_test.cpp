// tri6_positive: a straight triangle passes iff its corners are counter-clockwise; a mid-edge
// node pushed across the opposite corner fails; a mildly curved edge passes; a tri6 whose
// Jacobian is positive at the 6 nodes and the centroid but negative between them fails.
#include <gtest/gtest.h>

#include <array>
#include <utility>

#include "core/geometry/tri6_positive.h"

namespace cvtmesh {
namespace {

struct Tri6 {
  std::array<std::array<double, 2>, 3> c;
  std::array<std::array<double, 2>, 3> m;
  void straighten() {
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 2; ++a) m[k][a] = 0.5 * (c[kTri6Edge[k][0]][a] + c[kTri6Edge[k][1]][a]);
  }
  bool positive() const {
    const double* cc[3] = {c[0].data(), c[1].data(), c[2].data()};
    const double* mm[3] = {m[0].data(), m[1].data(), m[2].data()};
    return tri6_positive(cc, mm);
  }
};

Tri6 reference() {
  Tri6 t;
  t.c = {{{0, 0}, {1, 0}, {0, 1}}};
  t.straighten();
  return t;
}

TEST(Tri6Positive, StraightFollowsTheCornerOrientation) {
  Tri6 t = reference();
  EXPECT_TRUE(t.positive());
  std::swap(t.c[1], t.c[2]);  // clockwise
  t.straighten();
  EXPECT_FALSE(t.positive());
  // Any counter-clockwise straight triangle passes, a flat-ish one far from the origin too.
  Tri6 s;
  s.c = {{{1e6, 1e6}, {1e6 + 1, 1e6}, {1e6 + 0.5, 1e6 + 1e-9}}};
  s.straighten();
  EXPECT_TRUE(s.positive());
  // A flat one does not.
  s.c = {{{0, 0}, {1, 0}, {2, 0}}};
  s.straighten();
  EXPECT_FALSE(s.positive());
}

TEST(Tri6Positive, CurvedEdge) {
  Tri6 t = reference();
  // Edge (0,1) bulged outwards (away from vertex 2), then inwards a little: valid.
  t.m[0] = {0.5, -0.1};
  EXPECT_TRUE(t.positive());
  t.m[0] = {0.5, 0.1};
  EXPECT_TRUE(t.positive());
  // Pushed past the opposite corner: inverted.
  t.m[0] = {0.5, 1.2};
  EXPECT_FALSE(t.positive());
  // Slid along its edge past the quarter point: the Jacobian at corner 0 is negative.
  t.m[0] = {0.2, 0};
  EXPECT_FALSE(t.positive());
}

TEST(Tri6Positive, NegativeBetweenTheNodes) {
  // The 4 sub-triangles are positive and so is the Jacobian at the 6 nodes and the centroid,
  // but it is negative inside (about -0.04 near the edge (1,2)): its minimum is what fails.
  Tri6 t = reference();
  t.m[1] = {0.24, 0.83};
  t.m[2] = {0.21, 0.58};
  EXPECT_FALSE(t.positive());
  // Less far: positive everywhere.
  t.m[1] = {0.45, 0.6};
  t.m[2] = {0.05, 0.5};
  EXPECT_TRUE(t.positive());
}

}  // namespace
}  // namespace cvtmesh
