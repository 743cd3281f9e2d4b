#include "core/smoothing/smooth_maxmin3.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/mesh/check_mesh.h"
#include "core/mesh/vertex_tets.h"
#include "core/quality/quality.h"
#include "core/quality/quality_stats.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

using testing::global_min_quality;
using testing::make_tet_mesh;
using testing::nb_not_positive;
using testing::total_volume;
using testing::unoptimized_cube_sphere;

// The star of the free vertex 0 at (x0,y0,z0), |x0|+|y0|+|z0| < 1: 8 tets to the faces of the
// regular octahedron
// (+-1,0,0), (0,+-1,0), (0,0,+-1). By symmetry its centre maximises the minimum quality.
TetMesh octahedron_star(double x0, double y0, double z0) {
  std::vector<std::array<int, 4>> tets;
  for (int a : {1, 2})
    for (int y : {3, 4})
      for (int z : {5, 6}) tets.push_back({0, a, y, z});
  return make_tet_mesh(
      {{x0, y0, z0}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}, tets,
      /*interior=*/{0});
}

TEST(SmoothMaxMin3, RaisesTheMinimumOfABadlyPlacedVertexsStarToNearTheOptimum) {
  TetMesh m = octahedron_star(0.6, 0.2, -0.15);
  ASSERT_TRUE(check_mesh(m).ok);
  const TetMesh start = m;
  const double q0 = global_min_quality(m, Measure::kQ);
  const double a0 = global_min_quality(m, Measure::kMinAngle);
  const MaxMinStats s = smooth_maxmin3(m);
  EXPECT_EQ(s.nb_moved, 1);
  EXPECT_GT(s.nb_steps, 0);
  const double q1 = global_min_quality(m, Measure::kQ);
  EXPECT_GT(q1, q0);
  EXPECT_GE(global_min_quality(m, Measure::kMinAngle), a0);
  EXPECT_EQ(s.q_min_before, q0);
  EXPECT_EQ(s.q_min_after, q1);
  // The best possible minimum: the vertex at the centre.
  const double q_best = global_min_quality(octahedron_star(0, 0, 0), Measure::kQ);
  EXPECT_GT(q1, q_best - 0.02);
  EXPECT_LE(q1, q_best + 1e-9);
  // Never inverted, never a boundary vertex moved, connectivity untouched.
  EXPECT_EQ(nb_not_positive(m), 0);
  EXPECT_TRUE(check_mesh(m).ok);
  EXPECT_EQ(m.tets, start.tets);
  for (int v = 1; v < m.nb_vertices(); ++v)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(m.point(v)[k], start.point(v)[k]);
}

double tet_quality_of(const TetMesh& m, int t) {
  const int* v = &m.tets[4 * t];
  return tet_quality(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]), Measure::kQ);
}

// only_tets: a poor tet outside the flagged ones does not bring its vertices in; flagged, it does.
TEST(SmoothMaxMin3, OnlyTheFlaggedTetsCountAsPoor) {
  const TetMesh start = octahedron_star(0.6, 0.2, -0.15);
  std::vector<char> none(start.nb_tets(), 0), one(start.nb_tets(), 0);
  // Flag the star's worst tet.
  int worst = 0;
  for (int t = 1; t < start.nb_tets(); ++t)
    if (tet_quality_of(start, t) < tet_quality_of(start, worst)) worst = t;
  one[worst] = 1;
  MaxMinOptions o;
  TetMesh m = start;
  o.only_tets = &none;
  EXPECT_EQ(smooth_maxmin3(m, o).nb_tried, 0);
  EXPECT_EQ(m.xyz, start.xyz);
  ASSERT_LT(global_min_quality(start, Measure::kQ), o.q_below);
  o.only_tets = &one;
  const MaxMinStats s = smooth_maxmin3(m, o);
  EXPECT_EQ(s.nb_moved, 1);
  EXPECT_GT(global_min_quality(m, Measure::kQ), global_min_quality(start, Measure::kQ));
}

TEST(SmoothMaxMin3, NeverMovesABoundaryVertexAndLeavesAGoodStarAlone) {
  TetMesh m = octahedron_star(0.6, 0.2, -0.15);
  m.vclass[0].dim = 2;  // the same bad star, the vertex now on a surface
  const TetMesh start = m;
  const MaxMinStats s = smooth_maxmin3(m);
  EXPECT_EQ(s.nb_tried, 0);
  EXPECT_EQ(m.xyz, start.xyz);
  // At the centre all tets are above the thresholds: nothing to do.
  TetMesh c = octahedron_star(0, 0, 0);
  MaxMinOptions o;
  o.q_below = 0.3;
  o.angle_below = 20;
  ASSERT_GT(global_min_quality(c, Measure::kQ), o.q_below);
  const TetMesh c0 = c;
  EXPECT_EQ(smooth_maxmin3(c, o).nb_tried, 0);
  EXPECT_EQ(c.xyz, c0.xyz);
}

TEST(SmoothMaxMin3, RaisesANearFlatSliverWithoutInvertingAnyTet) {
  // The vertex sits just off the face (1,3,5): the tet (0,1,3,5) is a near-flat sliver. Every
  // accepted move must keep it (and all others) positively oriented.
  TetMesh m = octahedron_star(0.33, 0.33, 0.3299);
  ASSERT_EQ(nb_not_positive(m), 0);
  const double q0 = global_min_quality(m, Measure::kQ);
  ASSERT_LT(q0, 0.01);
  smooth_maxmin3(m);
  EXPECT_EQ(nb_not_positive(m), 0);
  EXPECT_GT(global_min_quality(m, Measure::kQ), q0);
}

TEST(SmoothMaxMin3, GuardsEveryTetNeverLowersTheMinimaAndIsDeterministic) {
  TetMesh m = unoptimized_cube_sphere();
  ASSERT_TRUE(check_mesh(m).ok);
  const TetMesh start = m;
  const double vol = total_volume(m);
  const auto q0 = element_qualities(m, Measure::kQ);
  const auto a0 = element_qualities(m, Measure::kMinAngle);
  const double qmin0 = *std::min_element(q0.begin(), q0.end());
  const double amin0 = *std::min_element(a0.begin(), a0.end());
  MaxMinOptions o;
  const MaxMinStats s = smooth_maxmin3(m, o);
  EXPECT_GT(s.nb_moved, 0);
  const auto q1 = element_qualities(m, Measure::kQ);
  const auto a1 = element_qualities(m, Measure::kMinAngle);
  const double qmin1 = *std::min_element(q1.begin(), q1.end());
  const double amin1 = *std::min_element(a1.begin(), a1.end());
  EXPECT_GE(qmin1, qmin0);
  EXPECT_GE(amin1, amin0);
  // The poor tets got fewer.
  auto nb_poor = [&](const std::vector<double>& q) {
    return std::count_if(q.begin(), q.end(), [&](double x) { return x < o.q_below; });
  };
  EXPECT_LT(nb_poor(q1), nb_poor(q0));
  EXPECT_EQ(s.q_min_after, qmin1);
  EXPECT_EQ(s.angle_min_after, amin1);
  // A tet at or above the floor stays there.
  const double qf = std::max(o.q_floor, qmin0), af = std::max(o.angle_floor, amin0);
  ASSERT_EQ(q0.size(), q1.size());
  for (std::size_t t = 0; t < q0.size(); ++t) {
    if (q0[t] >= qf) ASSERT_GE(q1[t], qf) << "tet " << t;
    if (a0[t] >= af) ASSERT_GE(a1[t], af) << "tet " << t;
  }
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_EQ(m.tets, start.tets);
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim < 3)
      for (int k = 0; k < 3; ++k) ASSERT_EQ(m.point(v)[k], start.point(v)[k]) << "vertex " << v;
  EXPECT_NEAR(total_volume(m), vol, 1e-12 * vol);
  // The same input gives the same output.
  TetMesh again = start;
  smooth_maxmin3(again, o);
  EXPECT_EQ(again.xyz, m.xyz);
}

TEST(SmoothMaxMin3, BadOptionsThrow) {
  TetMesh m = testing::cube6();
  MaxMinOptions o;
  o.passes = -1;
  EXPECT_THROW(smooth_maxmin3(m, o), std::invalid_argument);
}

}  // namespace
}  // namespace cvtmesh
