#include "core/swap/flip32.h"

#include <gtest/gtest.h>

#include "core/mesh/check_mesh.h"
#include "core/swap/apply_swap.h"
#include "core/swap/compact_tets.h"
#include "core/swap/flip23.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

using testing::boundary_faces;
using testing::local_edge;
using testing::ring_mesh;
using testing::tet_vertex_sets;
using testing::total_volume;

TEST(Flip32, ThreeTetsAroundAnEdgeBecomeTwo) {
  TetMesh m = ring_mesh(3);  // p = 0, q = 1, ring 2, 3, 4
  ASSERT_TRUE(check_mesh(m).ok);
  const auto outer = boundary_faces(m);
  const double vol = total_volume(m);
  const SwapPlan plan = flip32(m, 1, local_edge(m, 1, 0, 1));
  ASSERT_EQ(plan.status, SwapStatus::kOk);
  EXPECT_EQ(plan.new_ids.size(), 2u);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  const std::set<std::array<int, 4>> expected = {{0, 2, 3, 4}, {1, 2, 3, 4}};
  EXPECT_EQ(tet_vertex_sets(m), expected);
  EXPECT_EQ(boundary_faces(m), outer);
  EXPECT_NEAR(total_volume(m), vol, 1e-12 * vol);
  // One slot is dead until compaction.
  EXPECT_EQ(m.nb_tets(), 3);
  EXPECT_EQ(compact_tets(m), 1);
  EXPECT_EQ(m.nb_tets(), 2);
  EXPECT_EQ(m.tet_region.size(), 2u);
  EXPECT_TRUE(check_mesh(m).ok);
  EXPECT_EQ(tet_vertex_sets(m), expected);
}

TEST(Flip32, RefusesOtherRingSizesBoundaryEdgesAndNonConvexRings) {
  TetMesh four = ring_mesh(4);
  EXPECT_EQ(flip32(four, 0, local_edge(four, 0, 0, 1)).status, SwapStatus::kRingSize);
  // An edge on the boundary: a ring edge (2,3) lies in boundary triangles.
  TetMesh three = ring_mesh(3);
  EXPECT_EQ(flip32(three, 0, local_edge(three, 0, 2, 3)).status, SwapStatus::kBoundary);
  // Ring above q: the union is not convex at the edge, (r0,r1,r2,q) would be inverted.
  TetMesh high = ring_mesh(3, 1.0, 2.0);
  ASSERT_TRUE(check_mesh(high).ok);
  const auto before = tet_vertex_sets(high);
  EXPECT_EQ(flip32(high, 0, local_edge(high, 0, 0, 1)).status, SwapStatus::kNotConvex);
  EXPECT_EQ(tet_vertex_sets(high), before);
  EXPECT_TRUE(check_mesh(high).ok);
}

TEST(ApplySwap, ReusesFreeSlotsAndKeepsRegionsAndTagsInStep) {
  TetMesh m = ring_mesh(3);
  m.tet_tags = {11, 12, 13};
  const ConstrainedFaces cf = constrained_faces(m);
  std::vector<int> free_slots;
  SwapPlan down = plan_flip32(m, cf, 0, local_edge(m, 0, 0, 1));
  ASSERT_EQ(down.status, SwapStatus::kOk);
  apply_swap(m, down, &free_slots);
  ASSERT_EQ(free_slots.size(), 1u);
  const int dead = free_slots[0];
  EXPECT_LT(m.tets[4 * dead], 0);
  EXPECT_TRUE(check_mesh(m).ok);
  for (int id : down.new_ids) EXPECT_EQ(m.tet_tags[id], 0u);  // new tets have no Gmsh tag
  // The 2-3 flip back needs a third slot: it takes the dead one instead of appending.
  const int t = down.new_ids[0];
  const int f = testing::face_opposite(m, t, testing::face_opposite(m, t, 0) >= 0 ? 0 : 1);
  SwapPlan up = plan_flip23(m, cf, t, f);
  ASSERT_EQ(up.status, SwapStatus::kOk);
  apply_swap(m, up, &free_slots);
  EXPECT_TRUE(free_slots.empty());
  EXPECT_EQ(m.nb_tets(), 3);
  EXPECT_NE(std::find(up.new_ids.begin(), up.new_ids.end(), dead), up.new_ids.end());
  EXPECT_EQ(m.tet_tags.size(), 3u);
  EXPECT_EQ(m.tet_region, std::vector<int>(3, 1));
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  // An invalid plan (the edge (p, r0) is on the boundary) is never applied.
  int tb = 0;
  while (local_edge(m, tb, 0, 2) < 0) ++tb;
  SwapPlan bad = plan_flip32(m, cf, tb, local_edge(m, tb, 0, 2));
  EXPECT_EQ(bad.status, SwapStatus::kBoundary);
  EXPECT_THROW(apply_swap(m, bad), std::invalid_argument);
}

}  // namespace
}  // namespace cvtmesh
