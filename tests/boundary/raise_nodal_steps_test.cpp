// Raising the lowest nodal time steps (core/boundary/raise_nodal_steps.h): on a jittered box the
// smallest nodal step rises towards the target, no vertex falls below min(its step before, the
// target), the bounds hold (Q_min, the minimum and maximum dihedral angles, the smallest element
// step: the mesh's own, so none gets worse), face vertices stay on their faces and corners fixed,
// the mesh stays valid; a mesh above the target is left alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/boundary/discrete_boundary.h"
#include "core/boundary/raise_nodal_steps.h"
#include "core/mesh/check_mesh.h"
#include "core/quality/quality.h"
#include "core/quality/quality_stats.h"
#include "core/quality/time_step_guard.h"
#include "core/quality/vertex_time_step.h"
#include "tests/support/box_moves.h"
#include "tests/support/test_meshes.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

constexpr int kN = 4;  // the box [0, 4]^3, lattice spacing 1

// The box's lattice jittered within its faces and edges (test_meshes.h), deterministic.
TetMesh jittered_box(double amount) {
  return testing::jittered_box(kN, amount, 4242u);
}

// The options the pipeline passes: the mesh's extremes as bounds.
NodalRaiseOptions bounds_of(const TetMesh& m, double target) {
  const QualityStats q = quality_stats(m, "");
  NodalRaiseOptions o;
  o.target = target;
  o.q_floor = q.q_min;
  o.angle_floor = q.min_angle;
  o.angle_ceiling = std::min(150.0, q.max_angle);
  o.dt_floor = min_time_step(m);
  return o;
}

TEST(RaiseNodalSteps, TheLowestRiseWithinTheMeshExtremesAndFacesStayFlat) {
  TetMesh m = jittered_box(0.35);
  ASSERT_TRUE(check_mesh(m).ok);
  const TetMesh start = m;
  const BoundaryModel b = make_discrete_boundary(m);
  const VertexTimeSteps before = vertex_time_steps(m);
  const double low = min_vertex_time_step(m);
  const QualityStats q0 = quality_stats(m, "");
  const double dt0 = min_time_step(m);
  const NodalRaiseOptions o = bounds_of(m, 1.3 * low);
  const NodalRaiseStats st = raise_nodal_steps(m, b, o);
  ASSERT_TRUE(check_mesh(m).ok);
  EXPECT_EQ(testing::nb_not_positive(m), 0);
  EXPECT_GT(st.nb_low, 0);
  EXPECT_GT(st.nb_moved, 0);
  EXPECT_DOUBLE_EQ(st.min_before, low);
  const double now = min_vertex_time_step(m);
  EXPECT_NEAR(st.min_after, now, 1e-12 * now);
  EXPECT_GT(now, low * 1.01) << "the smallest nodal step did not rise";
  // No vertex below min(its step before, the target).
  const VertexTimeSteps after = vertex_time_steps(m);
  for (int v = 0; v < m.nb_vertices(); ++v)
    EXPECT_GE(after.dt(v), std::min(before.dt(v), o.target) * (1 - 1e-12)) << v;
  // The mesh's extremes: no row worse.
  const QualityStats q1 = quality_stats(m, "");
  EXPECT_GE(q1.q_min, q0.q_min);
  EXPECT_GE(q1.min_angle, q0.min_angle);
  EXPECT_LE(q1.max_angle, q0.max_angle);
  EXPECT_GE(min_time_step(m), dt0);
  // Box faces flat, corners fixed; some boundary vertex moved (the lowest steps are there).
  const auto moved = testing::box_moves(m, start, kN);
  EXPECT_GT(moved[1] + moved[2], 0);
}

// With the gradient's directions where the fixed ones fail (interior movers), the same
// invariants: no vertex below min(its step before, the target), no row of the mesh worse, the
// mesh valid, the smallest step at least as high as before.
TEST(RaiseNodalSteps, TheGradientDirectionsKeepTheBounds) {
  TetMesh m = jittered_box(0.35);
  const BoundaryModel b = make_discrete_boundary(m);
  const VertexTimeSteps before = vertex_time_steps(m);
  const double low = min_vertex_time_step(m);
  const QualityStats q0 = quality_stats(m, "");
  const double dt0 = min_time_step(m);
  NodalRaiseOptions o = bounds_of(m, 1.3 * low);
  o.gradient_directions = true;
  raise_nodal_steps(m, b, o);
  ASSERT_TRUE(check_mesh(m).ok);
  EXPECT_EQ(testing::nb_not_positive(m), 0);
  EXPECT_GT(min_vertex_time_step(m), low * 1.01);
  const VertexTimeSteps after = vertex_time_steps(m);
  for (int v = 0; v < m.nb_vertices(); ++v)
    EXPECT_GE(after.dt(v), std::min(before.dt(v), o.target) * (1 - 1e-12)) << v;
  const QualityStats q1 = quality_stats(m, "");
  EXPECT_GE(q1.q_min, q0.q_min);
  EXPECT_GE(q1.min_angle, q0.min_angle);
  EXPECT_LE(q1.max_angle, q0.max_angle);
  EXPECT_GE(min_time_step(m), dt0);
}

TEST(RaiseNodalSteps, AMeshAboveTheTargetIsLeftAlone) {
  TetMesh m = jittered_box(0.35);
  const TetMesh start = m;
  const BoundaryModel b = make_discrete_boundary(m);
  const NodalRaiseStats st = raise_nodal_steps(m, b, bounds_of(m, min_vertex_time_step(m)));
  EXPECT_EQ(st.nb_low, 0);
  EXPECT_EQ(st.nb_moved, 0);
  EXPECT_EQ(m.xyz, start.xyz);
}

// Without a geometry only interior vertices move; the boundary stays exactly where it was.
TEST(RaiseNodalSteps, WithoutGeometryOnlyInteriorVerticesMove) {
  TetMesh m = jittered_box(0.35);
  const TetMesh start = m;
  const double low = min_vertex_time_step(m);
  raise_nodal_steps(m, BoundaryModel{}, bounds_of(m, 1.3 * low));
  ASSERT_TRUE(check_mesh(m).ok);
  EXPECT_GE(min_vertex_time_step(m), low);
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (start.vclass[v].dim < 3)
      for (int d = 0; d < 3; ++d) EXPECT_EQ(m.point(v)[d], start.point(v)[d]) << v;
}

}  // namespace
}  // namespace cvtmesh
