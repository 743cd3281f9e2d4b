#include "core/geometry/predicates.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "core/geometry/tet_geometry.h"
#include "core/geometry/tetgen_library.h"

namespace cvtmesh {
namespace {

TEST(Predicates, SignConventions) {
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, d[3] = {0, 0, 1};
  EXPECT_GT(orient2d(a, b, c), 0);
  EXPECT_LT(orient2d(a, c, b), 0);
  EXPECT_GT(orient3d(a, b, c, d), 0);
  EXPECT_GT(tet_volume(a, b, c, d), 0);
  EXPECT_LT(orient3d(b, a, c, d), 0);
  const double in[3] = {0.25, 0.25, 0.25}, out[3] = {2, 2, 2};
  EXPECT_GT(insphere(a, b, c, d, in), 0);
  EXPECT_LT(insphere(a, b, c, d, out), 0);
  const double in2[2] = {0.3, 0.3}, out2[2] = {2, 2};
  EXPECT_GT(incircle(a, b, c, in2), 0);
  EXPECT_LT(incircle(a, b, c, out2), 0);
}

TEST(Predicates, ExactOnDegenerateInput) {
  // Collinear points with coordinates that round badly in floating point.
  const double a[2] = {0.1, 0.1}, b[2] = {0.2, 0.2},
               c[2] = {0.30000000000000004, 0.30000000000000004};
  EXPECT_EQ(orient2d(a, b, c), 0.0);
  // Cospherical: the 8 corners of a cube lie on one sphere.
  const double p0[3] = {0, 0, 0}, p1[3] = {1, 0, 0}, p2[3] = {0, 1, 0}, p3[3] = {0, 0, 1},
               p7[3] = {1, 1, 1};
  EXPECT_EQ(insphere(p0, p1, p2, p3, p7), 0.0);
  // Cocircular: the 4 corners of a square.
  const double s3[2] = {1, 1};
  EXPECT_EQ(incircle(p0, p1, p2, s3), 0.0);
  // Coplanar points far from the origin.
  const double q0[3] = {1e6 + 0.1, 1e6, 3}, q1[3] = {1e6 + 0.2, 1e6 + 0.1, 3},
               q2[3] = {1e6, 1e6 + 0.3, 3}, q3[3] = {1e6 + 0.7, 1e6 + 0.7, 3};
  EXPECT_EQ(orient3d(q0, q1, q2, q3), 0.0);
}

// orient2d and incircle decide the certain cases by Shewchuk's first filter, inline, and pass
// the others to the library: the sign is the library's (exact) one on random and on nearly
// degenerate points (collinear and cocircular up to a few ulps, far from the origin).
TEST(Predicates, FilteredOrient2dAndIncircleHaveTheLibrarysSign) {
  const TetgenLibrary& lib = tetgen_library();
  auto sign = [](double v) { return (v > 0) - (v < 0); };
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int orient_diff = 0, circle_diff = 0, nb_zero = 0;
  for (int i = 0; i < 200000; ++i) {
    const double shift = i % 3 == 0 ? 0 : i % 3 == 1 ? 1e3 : 1e7;
    double p[4][2];
    for (auto& q : p) q[0] = shift + u(rng), q[1] = shift + u(rng);
    if (i % 2) {  // nearly degenerate: c on the line ab, d on the circle of abc (to ulps)
      // On dyadic points (multiples of 2^-10) and t = k / 8, c is exactly on the line; then
      // moved by an ulp or not.
      for (int k = 0; k < 2; ++k)
        for (int c = 0; c < 2; ++c) p[k][c] = shift + std::round(u(rng) * 1024) / 1024;
      const double t = static_cast<double>(rng() % 17) / 8 - 0.5;
      p[2][0] = p[0][0] + t * (p[1][0] - p[0][0]);
      p[2][1] = p[0][1] + t * (p[1][1] - p[0][1]);
      if (i % 8 == 1) p[2][0] = std::nextafter(p[2][0], 1e300);
      const std::array<double, 2> o = tri_circumcenter2d(p[0], p[1], p[3]);
      const double r = std::hypot(p[0][0] - o[0], p[0][1] - o[1]), a = u(rng) * M_PI;
      p[2][0] = i % 4 == 1 ? p[2][0] : o[0] + r * std::cos(a);
      p[2][1] = i % 4 == 1 ? p[2][1] : o[1] + r * std::sin(a);
    }
    const double o = orient2d(p[0], p[1], p[2]);
    nb_zero += o == 0;
    orient_diff += sign(o) != sign(lib.orient2d(p[0], p[1], p[2]));
    circle_diff +=
        sign(incircle(p[0], p[1], p[3], p[2])) != sign(lib.incircle(p[0], p[1], p[3], p[2]));
  }
  EXPECT_EQ(orient_diff, 0);
  EXPECT_EQ(circle_diff, 0);
  EXPECT_GT(nb_zero, 0);  // some exactly collinear triples reached the exact evaluation
}

TEST(TetGeometry, CircumcenterIsEquidistant) {
  const double a[3] = {0.1, 0.2, 0.3}, b[3] = {1.3, 0.1, 0.2}, c[3] = {0.4, 1.1, 0.1},
               d[3] = {0.3, 0.2, 0.9};
  const Vec3 cc = tet_circumcenter(a, b, c, d);
  const double r = dist2(cc.data(), a);
  EXPECT_NEAR(dist2(cc.data(), b), r, 1e-12);
  EXPECT_NEAR(dist2(cc.data(), c), r, 1e-12);
  EXPECT_NEAR(dist2(cc.data(), d), r, 1e-12);
  const Vec3 tc = tri_circumcenter3d(a, b, c);
  EXPECT_NEAR(dist2(tc.data(), a), dist2(tc.data(), b), 1e-12);
  EXPECT_NEAR(dist2(tc.data(), a), dist2(tc.data(), c), 1e-12);
  EXPECT_NEAR(orient3d(a, b, c, tc.data()), 0.0, 1e-12);
  const auto c2 = tri_circumcenter2d(a, b, c);
  EXPECT_NEAR((c2[0] - a[0]) * (c2[0] - a[0]) + (c2[1] - a[1]) * (c2[1] - a[1]),
              (c2[0] - b[0]) * (c2[0] - b[0]) + (c2[1] - b[1]) * (c2[1] - b[1]), 1e-12);
}

}  // namespace
}  // namespace cvtmesh
