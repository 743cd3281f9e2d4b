#include "core/swap/flip23.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <thread>

#include "core/mesh/check_mesh.h"
#include "core/swap/apply_swap.h"
#include "core/swap/flip32.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

using testing::boundary_faces;
using testing::face_opposite;
using testing::make_tet_mesh;
using testing::tet_vertex_sets;
using testing::total_volume;

// Two tets sharing the triangle a=0, b=1, c=2 (equilateral, in z = 0); d = 3 below, e = 4 above.
TetMesh two_tets(double zd, double ze, double xe = 0) {
  const double s = std::sqrt(3.0) / 2;
  return make_tet_mesh({{1, 0, 0}, {-0.5, s, 0}, {-0.5, -s, 0}, {0, 0, zd}, {xe, 0, ze}},
                       {{0, 1, 2, 3}, {0, 1, 2, 4}});
}

TEST(Flip23, TwoTetsBecomeThreeAroundTheNewEdge) {
  TetMesh m = two_tets(-1, 1);
  ASSERT_TRUE(check_mesh(m).ok);
  const auto outer = boundary_faces(m);
  const double vol = total_volume(m);
  const SwapPlan plan = flip23(m, 0, face_opposite(m, 0, 3));
  ASSERT_EQ(plan.status, SwapStatus::kOk);
  EXPECT_EQ(plan.new_ids.size(), 3u);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_EQ(m.nb_tets(), 3);
  const std::set<std::array<int, 4>> expected = {{0, 1, 3, 4}, {1, 2, 3, 4}, {0, 2, 3, 4}};
  EXPECT_EQ(tet_vertex_sets(m), expected);
  EXPECT_EQ(boundary_faces(m), outer);
  EXPECT_NEAR(total_volume(m), vol, 1e-12 * vol);
  // The shared face is gone: every tet now holds the new edge (3,4).
  for (int t = 0; t < 3; ++t) {
    EXPECT_GE(face_opposite(m, t, 3), 0);
    EXPECT_GE(face_opposite(m, t, 4), 0);
  }
}

TEST(Flip23, ThenFlip32RestoresTheTwoTets) {
  TetMesh m = two_tets(-1, 1);
  const auto before = tet_vertex_sets(m);
  const double vol = total_volume(m);
  ASSERT_EQ(flip23(m, 1, face_opposite(m, 1, 4)).status, SwapStatus::kOk);
  // Remove the new edge (3,4) again from any of the three tets.
  int t = 0;
  while (m.tets[4 * t] < 0) ++t;
  const SwapPlan back = flip32(m, t, testing::local_edge(m, t, 3, 4));
  ASSERT_EQ(back.status, SwapStatus::kOk);
  EXPECT_TRUE(check_mesh(m).ok);
  EXPECT_EQ(tet_vertex_sets(m), before);
  EXPECT_NEAR(total_volume(m), vol, 1e-12 * vol);
}

TEST(Flip23, RefusesWhenTheUnionIsNotConvexAcrossTheFace) {
  // e far to the side: the segment d-e misses the triangle (a,b,c).
  TetMesh m = two_tets(-1, 0.2, 3.0);
  ASSERT_TRUE(check_mesh(m).ok);
  const auto before = tet_vertex_sets(m);
  const SwapPlan plan = flip23(m, 0, face_opposite(m, 0, 3));
  EXPECT_EQ(plan.status, SwapStatus::kNotConvex);
  EXPECT_EQ(tet_vertex_sets(m), before);
  EXPECT_TRUE(check_mesh(m).ok);
}

TEST(Flip23, NeverFlipsAConstrainedFace) {
  TetMesh m = two_tets(-1, 1);
  m.tris.insert(m.tris.end(), {0, 2, 1});  // the shared face, as an embedded surface
  m.tri_surface.push_back(2);
  ASSERT_TRUE(check_mesh(m).ok);
  const auto before = tet_vertex_sets(m);
  EXPECT_EQ(flip23(m, 0, face_opposite(m, 0, 3)).status, SwapStatus::kConstrainedFace);
  EXPECT_EQ(flip23(m, 1, face_opposite(m, 1, 4)).status, SwapStatus::kConstrainedFace);
  EXPECT_EQ(tet_vertex_sets(m), before);
  EXPECT_TRUE(check_mesh(m).ok);
}

TEST(Flip23, NeverMixesRegionsAndRefusesBoundaryFaces) {
  TetMesh m = two_tets(-1, 1);
  m.tet_region[1] = 2;
  m.tris.insert(m.tris.end(), {0, 1, 2});  // the interface
  m.tri_surface.push_back(2);
  ASSERT_TRUE(check_mesh(m).ok);
  // The interface is constrained; even when it is not listed, the regions differ.
  EXPECT_EQ(flip23(m, 0, face_opposite(m, 0, 3)).status, SwapStatus::kConstrainedFace);
  m.tris.resize(m.tris.size() - 3);
  m.tri_surface.pop_back();
  EXPECT_EQ(flip23(m, 0, face_opposite(m, 0, 3)).status, SwapStatus::kMixedRegions);
  EXPECT_EQ(m.nb_tets(), 2);
  // A face with no tet behind it.
  TetMesh b = two_tets(-1, 1);
  EXPECT_EQ(flip23(b, 0, face_opposite(b, 0, 0)).status, SwapStatus::kBoundary);
  EXPECT_THROW(flip23(b, 0, 4), std::invalid_argument);
  EXPECT_THROW(flip23(b, 7, 0), std::invalid_argument);
}

TEST(Flip23, CriterionRejectsAFlipThatLowersTheMinimumAndTheInverseOfAnAcceptedOne) {
  // Three tets around a long edge (p,q at +-1.5 over a unit triangle): the 3-2 flip improves
  // them, so the criterion accepts it and must then refuse the 2-3 flip that undoes it.
  TetMesh m = testing::ring_mesh(3, 1.5);
  const SwapCriterion q{Measure::kQ, 1e-6};
  const SwapPlan forward = flip32(m, 0, testing::local_edge(m, 0, 0, 1), &q);
  ASSERT_EQ(forward.status, SwapStatus::kOk);
  EXPECT_GT(forward.new_min, forward.old_min);
  ASSERT_TRUE(check_mesh(m).ok);
  const auto after = tet_vertex_sets(m);
  int t = 0;
  while (m.tets[4 * t] < 0) ++t;
  // The face shared by the two new tets is the one opposite p (vertex 0) or q (vertex 1).
  const int f = face_opposite(m, t, face_opposite(m, t, 0) >= 0 ? 0 : 1);
  const SwapPlan inverse = flip23(m, t, f, &q);
  EXPECT_EQ(inverse.status, SwapStatus::kRejected);
  EXPECT_EQ(tet_vertex_sets(m), after);
  EXPECT_TRUE(check_mesh(m).ok);
}

// apply_swap reuses per-thread arrays from one swap to the next: what a larger swap and a swap
// that threw half-way (a dead tet in its cavity) leave in them changes nothing in the next swap,
// which gives the same mesh as in a fresh thread.
TEST(Flip23, ApplySwapGivesTheSameMeshAfterOtherSwapsInTheSameThread) {
  TetMesh fresh = two_tets(-1, 1), reused = fresh;
  const ConstrainedFaces none;
  SwapPlan fresh_plan = plan_flip23(fresh, none, 0, face_opposite(fresh, 0, 3));
  SwapPlan reused_plan = fresh_plan;
  ASSERT_EQ(fresh_plan.status, SwapStatus::kOk);
  std::thread([&] { apply_swap(fresh, fresh_plan); }).join();
  // This thread first: a 3-2 flip (a larger cavity), then a swap that throws after listing the
  // faces of its first tet.
  {
    TetMesh m = two_tets(-1, 1);
    ASSERT_EQ(flip23(m, 0, face_opposite(m, 0, 3)).status, SwapStatus::kOk);
    int t = 0;
    while (m.tets[4 * t] < 0) ++t;
    ASSERT_EQ(flip32(m, t, testing::local_edge(m, t, 3, 4)).status, SwapStatus::kOk);
    TetMesh dead = two_tets(-1, 1);
    SwapPlan bad = plan_flip23(dead, none, 0, face_opposite(dead, 0, 3));
    ASSERT_EQ(bad.status, SwapStatus::kOk);
    dead.tets[4] = -1;  // tet 1, the plan's second old tet, is dead now
    EXPECT_THROW(apply_swap(dead, bad), std::invalid_argument);
  }
  apply_swap(reused, reused_plan);
  EXPECT_EQ(reused.tets, fresh.tets);
  EXPECT_EQ(reused.adj, fresh.adj);
  EXPECT_EQ(reused_plan.new_ids, fresh_plan.new_ids);
  EXPECT_TRUE(check_mesh(reused).ok);
}

}  // namespace
}  // namespace cvtmesh
