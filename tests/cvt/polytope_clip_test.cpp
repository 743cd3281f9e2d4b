#include "core/cvt/polytope_clip.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace cvtmesh {
namespace {

// The 2^k pieces cut from a tet by k planes (every choice of side) partition it: their volumes,
// first and second moments add up to the tet's.
TEST(PolytopeClip, PiecesFromAllSidesOfRandomPlanesPartitionTheTet) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const double p[4][3] = {{0, 0, 0}, {1, 0.1, 0}, {0.2, 1, 0.1}, {0.1, 0.3, 1.2}};
  Polytope whole, piece, scratch;
  tet_polytope(p[0], p[1], p[2], p[3], whole);
  const Vec3 z{0.3, 0.2, 0.1};
  const Moments full = polytope_moments(whole, z);
  EXPECT_NEAR(full.m0,
              1.0 / 6.0 * std::fabs(1 * (1 * 1.2 - 0.1 * 0.3) - 0.1 * (0.2 * 1.2 - 0.1 * 0.1)),
              1e-12);
  for (int trial = 0; trial < 50; ++trial) {
    const int k = 1 + trial % 4;
    std::vector<Vec3> n(k);
    std::vector<double> d(k);
    for (int i = 0; i < k; ++i) {
      n[i] = {u(rng), u(rng), u(rng)};
      d[i] = dot(n[i], Vec3{0.3, 0.3, 0.3}) + 0.3 * u(rng);
    }
    Moments sum;
    for (int mask = 0; mask < (1 << k); ++mask) {
      tet_polytope(p[0], p[1], p[2], p[3], piece);
      bool alive = true;
      for (int i = 0; i < k && alive; ++i) {
        const double s = (mask >> i) & 1 ? 1.0 : -1.0;
        alive = clip_polytope(piece, s * n[i], s * d[i], 4 + i, 1e-13, scratch);
      }
      if (alive) sum.add(polytope_moments(piece, z));
    }
    EXPECT_NEAR(sum.m0, full.m0, 1e-12) << trial;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum.m1[c], full.m1[c], 1e-12) << trial;
    for (int c = 0; c < 9; ++c) EXPECT_NEAR(sum.m2[c], full.m2[c], 1e-12) << trial;
  }
}

// Cutting a tet through a vertex and an edge (points exactly on the plane) keeps a valid piece.
TEST(PolytopeClip, PlaneThroughVerticesGivesTheExactHalf) {
  const double p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Polytope t, scratch;
  tet_polytope(p[0], p[1], p[2], p[3], t);
  // The plane x = y contains vertices 0 and 3: it halves the tet.
  ASSERT_TRUE(clip_polytope(t, Vec3{1, -1, 0}, 0.0, 4, 1e-13, scratch));
  EXPECT_NEAR(polytope_moments(t, Vec3{0, 0, 0}).m0, 1.0 / 12.0, 1e-15);
  EXPECT_NEAR(face_area(t, 4), 0.5 * std::sqrt(2.0) * 1.0 / 2.0, 1e-15);
  // A plane that only touches a vertex keeps everything; one beyond it keeps nothing.
  tet_polytope(p[0], p[1], p[2], p[3], t);
  EXPECT_TRUE(clip_polytope(t, Vec3{1, 0, 0}, 1.0, 4, 1e-13, scratch));
  EXPECT_NEAR(polytope_moments(t, Vec3{0, 0, 0}).m0, 1.0 / 6.0, 1e-15);
  EXPECT_FALSE(clip_polytope(t, Vec3{-1, 0, 0}, -1.0, 4, 1e-13, scratch));
}

}  // namespace
}  // namespace cvtmesh
