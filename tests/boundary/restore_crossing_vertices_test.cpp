// The local repair of a boundary that the free boundary made cross itself.
#include "core/boundary/restore_crossing_vertices.h"

#include <gtest/gtest.h>

#include "core/mesh/check_mesh.h"
#include "core/mesh/find_surface_intersections.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

std::vector<int> tris_of(const TetMesh& m) {
  return std::vector<int>(m.tris.begin(), m.tris.end());
}

// Three separate tets; a corner of the second moved into the first makes their surfaces cross,
// and a corner of the third moved away from everything. After the repair nothing crosses, the
// crossing corner is back at its input position, every tet is positive, the other move is kept.
TEST(RestoreCrossingVertices, PutsTheCrossingTrianglesVerticesBackAndNothingElse) {
  const std::vector<std::array<double, 3>> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                                  {2, 0, 0}, {3, 0, 0}, {2, 1, 0}, {2, 0, 1},
                                                  {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1}};
  const TetMesh input = testing::make_tet_mesh(pts, {{0, 1, 2, 3}, {4, 5, 6, 7}, {8, 9, 10, 11}});
  ASSERT_TRUE(find_surface_intersections(input.xyz, tris_of(input)).empty());
  TetMesh mesh = input;
  mesh.xyz[3 * 4 + 0] = 0.2, mesh.xyz[3 * 4 + 1] = 0.2, mesh.xyz[3 * 4 + 2] = 0.2;
  mesh.xyz[3 * 9 + 0] = 6.5;  // a move far from any crossing
  ASSERT_FALSE(find_surface_intersections(mesh.xyz, tris_of(mesh)).empty());
  const RestoreCrossingStats st = restore_crossing_vertices(mesh, input);
  EXPECT_GT(st.nb_pairs_before, 0);
  EXPECT_EQ(st.nb_pairs_after, 0);
  EXPECT_EQ(st.nb_restored, 1);
  EXPECT_TRUE(find_surface_intersections(mesh.xyz, tris_of(mesh)).empty());
  for (int k = 0; k < 3; ++k) EXPECT_EQ(mesh.point(4)[k], input.point(4)[k]);
  EXPECT_EQ(mesh.point(9)[0], 6.5);
  EXPECT_TRUE(check_mesh(mesh).ok);
  // An input that already crosses itself: nothing is the optimizer's doing, nothing moves.
  TetMesh crossed = mesh;
  crossed.xyz[3 * 4 + 0] = 0.2, crossed.xyz[3 * 4 + 1] = 0.2, crossed.xyz[3 * 4 + 2] = 0.2;
  TetMesh again = crossed;
  const RestoreCrossingStats none = restore_crossing_vertices(again, crossed);
  EXPECT_EQ(none.nb_restored, 0);
  EXPECT_EQ(again.xyz, crossed.xyz);
}

}  // namespace
}  // namespace cvtmesh
