#include "core/mesh/check_mesh.h"

#include <gtest/gtest.h>

#include "core/mesh/build_adjacency.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

TEST(CheckMesh, CubeOfSixTetsIsValid) {
  TetMesh m = testing::cube6();
  EXPECT_EQ(m.nb_tris(), 12);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  // Adjacency is symmetric and every tet has 2 interior neighbours in the Kuhn cube.
  for (int t = 0; t < m.nb_tets(); ++t) {
    int inner = 0;
    for (int f = 0; f < 4; ++f)
      if (m.adj[4 * t + f] >= 0) {
        ++inner;
        EXPECT_EQ(m.adj[m.adj[4 * t + f]], 4 * t + f);
      }
    EXPECT_EQ(inner, 2);
  }
}

TEST(CheckMesh, DetectsInversionOpenBoundaryAndBrokenAdjacency) {
  TetMesh m = testing::cube6();
  std::swap(m.tets[0], m.tets[1]);
  build_adjacency(m);
  EXPECT_EQ(check_mesh(m).nb_inverted, 1);

  m = testing::cube6();
  m.tris.resize(m.tris.size() - 3);
  m.tri_surface.pop_back();
  EXPECT_EQ(check_mesh(m).nb_open_faces, 1);

  m = testing::cube6();
  for (int& a : m.adj)
    if (a >= 0) {
      a = -1;
      break;
    }
  EXPECT_FALSE(check_mesh(m).ok);

  m = testing::cube6();
  m.tris.insert(m.tris.end(), {0, 3, 5});
  m.tri_surface.push_back(2);
  EXPECT_EQ(check_mesh(m).nb_dangling_constraints, 1);
}

TEST(CheckMesh, NonManifoldFaceThrows) {
  TetMesh m = testing::cube6();
  m.tets.insert(m.tets.end(), m.tets.begin(), m.tets.begin() + 4);
  m.tet_region.push_back(1);
  EXPECT_THROW(build_adjacency(m), std::exception);
}

TEST(CheckMesh, SquareOfTwoTrianglesIsValidAndInversionIsDetected) {
  TriMesh2 m = testing::square2();
  EXPECT_TRUE(check_mesh(m).ok);
  EXPECT_EQ(m.adj[m.adj[0 * 3 + 1]], 1);  // edge opposite vertex 1 of t0 is the diagonal
  std::swap(m.tris[1], m.tris[2]);
  build_adjacency2(m);
  EXPECT_EQ(check_mesh(m).nb_inverted, 1);
}

}  // namespace
}  // namespace cvtmesh
