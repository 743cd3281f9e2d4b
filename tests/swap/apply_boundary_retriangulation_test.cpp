#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh/build_adjacency.h"
#include "core/mesh/check_mesh.h"
#include "core/swap/apply_swap.h"
#include "core/util/error.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

using testing::make_tet_mesh;
using testing::tet_vertex_sets;

// The open ring of two tets around the boundary edge (0, 1) (0 below, 1 above the plane z = 0,
// 2, 3, 4 on the unit circle at 0, 120 and 240 degrees), and a fourth tet (0, 2, 3, 5) behind
// their face (0, 2, 3) -- 5 outside the circle between 2 and 3.
TetMesh open_ring_with_neighbour() {
  const double s = std::sqrt(3.0) / 2;
  return make_tet_mesh(
      {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {-0.5, s, 0}, {-0.5, -s, 0}, {1, 1, -0.5}},
      {{0, 1, 2, 3}, {0, 1, 3, 4}, {0, 2, 3, 5}});
}

std::array<int, 4> oriented(const TetMesh& m, std::array<int, 4> t) {
  if (orient3d(m.point(t[0]), m.point(t[1]), m.point(t[2]), m.point(t[3])) < 0)
    std::swap(t[2], t[3]);
  return t;
}

// The flip of the boundary edge (0, 1) to (2, 4): the ring's two tets become (2, 3, 4, 0) and
// (2, 3, 4, 1); the adjacency repaired in place is the one a rebuild gives, the neighbour behind
// (0, 2, 3) included, and the new faces (0, 2, 4), (1, 2, 4) are boundary faces.
TEST(ApplyBoundaryRetriangulation, LinksTheNewTetsAsARebuildWould) {
  TetMesh m = open_ring_with_neighbour();
  if (m.adj.size() != m.tets.size()) build_adjacency(m);
  ASSERT_EQ(last_non_positive_tet(m), -1);
  const int region = m.tet_region[0];
  const std::vector<int> slots = apply_boundary_retriangulation(
      m, {0, 1}, {oriented(m, {2, 3, 4, 0}), oriented(m, {2, 3, 4, 1})}, region);
  ASSERT_EQ(slots, (std::vector<int>{3, 4}));  // appended
  EXPECT_LT(m.tets[0], 0);
  EXPECT_LT(m.tets[4], 0);
  EXPECT_EQ(last_non_positive_tet(m), -1);
  TetMesh rebuilt = m;
  build_adjacency(rebuilt);
  EXPECT_EQ(m.adj, rebuilt.adj);
  EXPECT_EQ(tet_vertex_sets(m),
            (std::set<std::array<int, 4>>{{0, 2, 3, 4}, {1, 2, 3, 4}, {0, 2, 3, 5}}));
  EXPECT_EQ(m.tet_region[3], region);
  EXPECT_EQ(m.tet_region[4], region);
  // The neighbour's face (0, 2, 3) now faces the new tet (2, 3, 4, 0).
  int linked = 0;
  for (int f = 0; f < 4; ++f) {
    const int o = m.adj[4 * 2 + f];
    if (o >= 0) linked += o / 4 == 3;
  }
  EXPECT_EQ(linked, 1);
}

// New tets that leave a face with a tet behind it uncovered are refused before anything
// changes: the mesh would come apart there.
TEST(ApplyBoundaryRetriangulation, RefusesToUncoverAFaceWithATetBehind) {
  TetMesh m = open_ring_with_neighbour();
  if (m.adj.size() != m.tets.size()) build_adjacency(m);
  const TetMesh before = m;
  // (0, 1, 2, 3) replaced by (1, 2, 3, 4) only: its face (0, 2, 3), behind which tet 2 stands,
  // is covered by nothing.
  EXPECT_THROW(apply_boundary_retriangulation(m, {0}, {oriented(m, {1, 2, 3, 4})}, m.tet_region[0]),
               InvariantError);
  EXPECT_EQ(m.tets, before.tets);
  EXPECT_EQ(m.adj, before.adj);
  m.adj.clear();
  EXPECT_THROW(apply_boundary_retriangulation(m, {0}, {oriented(m, {1, 2, 3, 4})}, 0),
               std::invalid_argument);
}

}  // namespace
}  // namespace cvtmesh
