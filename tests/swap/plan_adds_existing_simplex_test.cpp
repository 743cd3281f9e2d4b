#include "core/swap/plan_adds_existing_simplex.h"

#include <gtest/gtest.h>

#include "core/mesh/build_adjacency.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

using testing::ring_mesh;

// The removal of edge (0, 1) of the ring of 4 tets, triangulating the ring polygon r0 r1 r2 r3
// (vertices 2..5) with the diagonal (2, 4) or (3, 5).
SwapPlan removal_with_diagonal(int a, int b, int c, int d) {
  SwapPlan plan;
  plan.old_tets = {0, 1, 2, 3};
  // Triangles (a, b, c) and (a, c, d) of the square, each with q = 1 above and p = 0 below.
  plan.new_tets = {{a, b, c, 1}, {a, c, b, 0}, {a, c, d, 1}, {a, d, c, 0}};
  return plan;
}

// On a valid ring both triangulations add only simplices no other tet holds; once a tet outside
// the ring holds the diagonal (2, 4) -- a fold: the tet (0, 2, 3, 4) on the ring's outer face
// (0, 2, 3) reaches back to r2 -- the triangulation with that diagonal is refused and the other
// is not. A 3-2 flip (no new edge) whose new triangle some other tet holds is refused too.
TEST(PlanAddsExistingSimplex, RefusesANewEdgeOrFaceThatAnotherTetHolds) {
  TetMesh m = ring_mesh(4);
  const SwapPlan with_24 = removal_with_diagonal(2, 3, 4, 5);
  const SwapPlan with_35 = removal_with_diagonal(3, 4, 5, 2);
  EXPECT_FALSE(plan_adds_existing_simplex(m, with_24));
  EXPECT_FALSE(plan_adds_existing_simplex(m, with_35));

  TetMesh folded = m;
  folded.tets.insert(folded.tets.end(), {0, 3, 2, 4});
  folded.tet_region.push_back(folded.tet_region[0]);
  build_adjacency(folded);
  EXPECT_TRUE(plan_adds_existing_simplex(folded, with_24));
  EXPECT_FALSE(plan_adds_existing_simplex(folded, with_35));

  TetMesh ring3 = ring_mesh(3);
  SwapPlan flip32;
  flip32.old_tets = {0, 1, 2};
  flip32.new_tets = {{2, 3, 4, 1}, {2, 4, 3, 0}};
  EXPECT_FALSE(plan_adds_existing_simplex(ring3, flip32));
  ring3.tets.insert(ring3.tets.end(), {0, 3, 2, 4});
  ring3.tet_region.push_back(ring3.tet_region[0]);
  build_adjacency(ring3);
  EXPECT_TRUE(plan_adds_existing_simplex(ring3, flip32));
}

}  // namespace
}  // namespace cvtmesh
