// Removal of the cap vertices whose nodal time step is low (core/boundary/remove_low_step_caps.h)
// on a hand-made cap: the tet (a, b, c, d) under a triangle (a, b, c) in z = 0, and a flat tet
// (a, b, c, p) whose apex p lies just above the middle of (a, b, c): p is a surface vertex of
// valence 3 standing on one tet (igl_cheburashka's lowest nodal step after the free boundary), its
// nodal step the cap's height. Below the target it goes: the mesh is the tet (a, b, c, d), valid,
// p in no element and fixed, no vertex's nodal step below min(its step before, the target), the
// smallest one up, no quality row worse. Above the target, or with a Hausdorff tolerance below
// p's height, nothing changes.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/collapse_boundary_edges.h"
#include "core/boundary/discrete_boundary.h"
#include "core/boundary/remove_low_step_caps.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/vertex_tets.h"
#include "core/quality/quality_stats.h"
#include "core/quality/vertex_time_step.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

constexpr int kP = 4;  // a, b, c, d, p

TetMesh capped(double height) {
  return testing::make_tet_mesh(
      {{{0, 0, 0}}, {{1, 0, 0}}, {{0.5, 0.9, 0}}, {{0.5, 0.3, -0.8}}, {{0.5, 0.3, height}}},
      {{{0, 1, 2, 3}}, {{0, 1, 2, kP}}});
}

TEST(RemoveLowStepCaps, TheCapVertexGoesAndNoNodalStepFalls) {
  TetMesh m = capped(5e-3);
  ASSERT_TRUE(check_mesh(m).ok);
  BoundaryModel b = make_discrete_boundary(m);
  ASSERT_TRUE(is_cap_vertex(m, b, vertex_tets(m), boundary_fans(m), kP));
  for (int v = 0; v < kP; ++v)
    EXPECT_FALSE(is_cap_vertex(m, b, vertex_tets(m), boundary_fans(m), v)) << v;
  const VertexTimeSteps before = vertex_time_steps(m);
  const double low = min_vertex_time_step(m);
  ASSERT_EQ(low, before.dt(kP));  // the cap's apex has the lowest step
  const QualityStats q0 = quality_stats(m, "");
  LowCapOptions o;
  o.target = 2 * low;
  o.hausdorff = 0.02;
  const LowCapStats st = remove_low_step_caps(m, b, o);
  EXPECT_EQ(st.nb_caps, 1);
  EXPECT_EQ(st.nb_removed, 1);
  const MeshCheck c = check_mesh(m);
  ASSERT_TRUE(c.ok) << c.problems.front();
  ASSERT_EQ(m.nb_tets(), 1);
  ASSERT_EQ(m.nb_tris(), 4);
  for (int x : m.tets) EXPECT_NE(x, kP);
  for (int x : m.tris) EXPECT_NE(x, kP);
  EXPECT_EQ(b.role_of(kP).role, BoundaryRole::kFixed);
  const VertexTimeSteps after = vertex_time_steps(m);
  for (int v = 0; v < kP; ++v)
    EXPECT_GE(after.dt(v), std::min(before.dt(v), o.target) * (1 - 1e-12)) << v;
  EXPECT_GT(min_vertex_time_step(m), low);
  const QualityStats q1 = quality_stats(m, "");
  EXPECT_GE(q1.q_min, q0.q_min);
  EXPECT_GE(q1.min_angle, q0.min_angle);
  EXPECT_LE(q1.max_angle, q0.max_angle);
}

TEST(RemoveLowStepCaps, AboveTheTargetOrBeyondTheHausdorffBoundNothingChanges) {
  for (const bool above : {true, false}) {
    TetMesh m = capped(5e-3);
    BoundaryModel b = make_discrete_boundary(m);
    const TetMesh start = m;
    LowCapOptions o;
    o.target = above ? min_vertex_time_step(m) : 2 * min_vertex_time_step(m);
    o.hausdorff = above ? 0.02 : 2.5e-3;  // p is 5e-3 from the triangle that would be left
    const LowCapStats st = remove_low_step_caps(m, b, o);
    EXPECT_EQ(st.nb_removed, 0) << above;
    EXPECT_EQ(m.tets, start.tets) << above;
    EXPECT_EQ(m.tris, start.tris) << above;
    EXPECT_EQ(b.role_of(kP).role, make_discrete_boundary(start).role_of(kP).role) << above;
  }
}

}  // namespace
}  // namespace cvtmesh
