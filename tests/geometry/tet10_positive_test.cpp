// tet10_positive: a straight tet passes iff its corners are positive; a mid-edge node pushed
// across the opposite face fails; a mildly curved edge passes.
#include <gtest/gtest.h>

#include <array>

#include "core/geometry/tet10_positive.h"

namespace cvtmesh {
namespace {

struct Tet10 {
  std::array<std::array<double, 3>, 4> c;
  std::array<std::array<double, 3>, 6> m;
  void straighten() {
    for (int k = 0; k < 6; ++k)
      for (int a = 0; a < 3; ++a) m[k][a] = 0.5 * (c[kTet10Edge[k][0]][a] + c[kTet10Edge[k][1]][a]);
  }
  bool positive() const {
    const double* cc[4] = {c[0].data(), c[1].data(), c[2].data(), c[3].data()};
    const double* mm[6];
    for (int k = 0; k < 6; ++k) mm[k] = m[k].data();
    return tet10_positive(cc, mm);
  }
};

Tet10 reference() {
  Tet10 t;
  t.c = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  t.straighten();
  return t;
}

TEST(Tet10Positive, StraightFollowsTheCornerOrientation) {
  Tet10 t = reference();
  EXPECT_TRUE(t.positive());
  std::swap(t.c[0], t.c[1]);  // negative corner tet
  t.straighten();
  EXPECT_FALSE(t.positive());
  // Any positive straight tet passes, whatever its shape (a flat-ish sliver too).
  Tet10 s;
  s.c = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, 1e-3}}};
  s.straighten();
  EXPECT_TRUE(s.positive());
}

TEST(Tet10Positive, CurvedEdge) {
  Tet10 t = reference();
  // Edge (0,1) bulged slightly outwards (away from vertex 2 and 3): still valid.
  t.m[0] = {0.5, -0.05, -0.05};
  EXPECT_TRUE(t.positive());
  // Pushed through the opposite face x + y + z = 1: inverted.
  t.m[0] = {0.5, 0.6, 0.6};
  EXPECT_FALSE(t.positive());
}

}  // namespace
}  // namespace cvtmesh
