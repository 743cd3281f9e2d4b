#include "core/swap/flip32.h"

#include <gtest/gtest.h>

#include "core/mesh/check_mesh.h"
#include "core/swap/compact_tets.h"
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

}  // namespace
}  // namespace cvtmesh
