// Raising the smallest dihedral angles (core/boundary/raise_min_angles.h): on a jittered box the
// smallest dihedral angle rises, no tet's smallest angle falls below min(its value before, the
// target), the bounds hold (Q_min, the maximum dihedral angle, the smallest element step: the
// mesh's own, so none gets worse), the average Q does not fall, face vertices stay on their faces
// and corners fixed, the mesh stays valid; a mesh above the target is left alone; without a
// geometry only interior vertices move.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "core/boundary/discrete_boundary.h"
#include "core/boundary/raise_min_angles.h"
#include "core/mesh/check_mesh.h"
#include "core/quality/quality.h"
#include "core/quality/quality_stats.h"
#include "core/quality/time_step_guard.h"
#include "tests/support/box_moves.h"
#include "tests/support/test_meshes.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

constexpr int kN = 4;  // the box [0, 4]^3, lattice spacing 1

TetMesh jittered_box(double amount) {
  return testing::jittered_box(kN, amount, 4242u);
}

// The options the pipeline passes: the mesh's extremes as bounds.
AngleRaiseOptions bounds_of(const TetMesh& m, double target) {
  const QualityStats q = quality_stats(m, "");
  AngleRaiseOptions o;
  o.target = target;
  o.q_floor = q.q_min;
  o.angle_ceiling = std::min(150.0, q.max_angle);
  o.dt_floor = min_time_step(m);
  return o;
}

std::vector<double> min_angles(const TetMesh& m) {
  std::vector<double> a;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * static_cast<std::size_t>(t)];
    a.push_back(tet_table_qualities(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]))[2]);
  }
  return a;
}

TEST(RaiseMinAngles, TheSmallestRiseWithinTheMeshExtremesAndFacesStayFlat) {
  TetMesh m = jittered_box(0.35);
  ASSERT_TRUE(check_mesh(m).ok);
  const TetMesh start = m;
  const BoundaryModel b = make_discrete_boundary(m);
  const QualityStats q0 = quality_stats(m, "");
  const std::vector<double> before = min_angles(m);
  const double dt0 = min_time_step(m);
  const AngleRaiseOptions o = bounds_of(m, 1.3 * q0.min_angle);
  const AngleRaiseStats st = raise_min_angles(m, b, o);
  ASSERT_TRUE(check_mesh(m).ok);
  EXPECT_EQ(testing::nb_not_positive(m), 0);
  EXPECT_GT(st.nb_low, 0);
  EXPECT_GT(st.nb_moved, 0);
  EXPECT_NEAR(st.min_before, q0.min_angle, 1e-9);
  const QualityStats q1 = quality_stats(m, "");
  EXPECT_NEAR(st.min_after, q1.min_angle, 1e-9);
  EXPECT_GT(q1.min_angle, q0.min_angle + 0.01) << "the smallest dihedral angle did not rise";
  // No tet below min(its smallest angle before, the target).
  const std::vector<double> after = min_angles(m);
  for (std::size_t t = 0; t < after.size(); ++t)
    EXPECT_GE(after[t], std::min(before[t], o.target) - 1e-9) << t;
  // The mesh's other extremes: no row worse.
  EXPECT_GE(q1.q_min, q0.q_min);
  EXPECT_LE(q1.max_angle, q0.max_angle);
  EXPECT_GE(q1.q_avg, q0.q_avg - 1e-12);
  EXPECT_GE(min_time_step(m), dt0);
  // Box faces flat, corners fixed; some boundary vertex moved.
  const auto moved = testing::box_moves(m, start, kN);
  EXPECT_GT(moved[1] + moved[2], 0);
}

TEST(RaiseMinAngles, AMeshAboveTheTargetIsLeftAlone) {
  TetMesh m = jittered_box(0.35);
  const TetMesh start = m;
  const BoundaryModel b = make_discrete_boundary(m);
  const AngleRaiseStats st = raise_min_angles(m, b, bounds_of(m, quality_stats(m, "").min_angle));
  EXPECT_EQ(st.nb_low, 0);
  EXPECT_EQ(st.nb_moved, 0);
  EXPECT_EQ(m.xyz, start.xyz);
}

// Without a geometry only interior vertices move; the boundary stays exactly where it was.
TEST(RaiseMinAngles, WithoutGeometryOnlyInteriorVerticesMove) {
  TetMesh m = jittered_box(0.35);
  const TetMesh start = m;
  const double low = quality_stats(m, "").min_angle;
  raise_min_angles(m, BoundaryModel{}, bounds_of(m, 1.3 * low));
  ASSERT_TRUE(check_mesh(m).ok);
  EXPECT_GE(quality_stats(m, "").min_angle, low);
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (start.vclass[v].dim < 3)
      for (int d = 0; d < 3; ++d) EXPECT_EQ(m.point(v)[d], start.point(v)[d]) << v;
}

}  // namespace
}  // namespace cvtmesh
