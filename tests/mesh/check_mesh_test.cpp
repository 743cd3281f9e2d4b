#include "core/mesh/check_mesh.h"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "core/geometry/predicates.h"
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
  // Reported as inverted, not also as overlapping its neighbours.
  EXPECT_EQ(check_mesh(m).nb_bad_adjacency, 0);

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

// Two positive tets on the same side of their common face (3 and 4 both above the triangle
// (0, 1, 2)) overlap; build_adjacency pairs them anyway (it matches vertex ids only), and before
// this check nothing else flagged it: every tet positive, every open face a boundary triangle.
TEST(CheckMesh, DetectsTetsOverlappingAcrossTheirCommonFace) {
  const std::vector<std::array<double, 3>> pts = {{0, 0, 0},     {1, 0, 0},      {0, 1, 0},
                                                  {0.2, 0.2, 1}, {0.3, 0.25, 2}, {0.2, 0.2, -1}};
  TetMesh m = testing::make_tet_mesh(pts, {{0, 1, 2, 3}, {0, 1, 2, 4}});
  MeshCheck c = check_mesh(m);
  EXPECT_FALSE(c.ok);
  EXPECT_EQ(c.nb_bad_adjacency, 2);  // seen from each tet
  ASSERT_FALSE(c.problems.empty());
  EXPECT_NE(c.problems[0].find("overlap"), std::string::npos) << c.problems[0];
  // The same two tets with 4 below instead: valid.
  m = testing::make_tet_mesh(pts, {{0, 1, 2, 3}, {0, 1, 2, 5}});
  c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
}

// A boundary triangle held by more than one tet on the same side, or by two tets that are not
// linked, is refused: the face of a third tet, or of an unlinked one, looked like boundary.
TEST(CheckMesh, DetectsABoundaryTriangleHeldByTooManyTets) {
  const std::vector<std::array<double, 3>> pts = {{0, 0, 0},     {1, 0, 0},      {0, 1, 0},
                                                  {0.2, 0.2, 1}, {0.3, 0.25, 2}, {0.2, 0.2, -1}};
  // (0, 1, 2) a boundary triangle of the tet above it; a second tet above it, unlinked.
  TetMesh m = testing::make_tet_mesh(pts, {{0, 1, 2, 3}, {0, 1, 2, 5}});
  ASSERT_TRUE(check_mesh(m).ok);
  for (int& a : m.adj) a = -1;
  m.tris.insert(m.tris.end(), {0, 1, 2});
  m.tri_surface.push_back(2);
  MeshCheck c = check_mesh(m);  // two tets on (0, 1, 2), on its two sides, not adjacent
  EXPECT_FALSE(c.ok);
  EXPECT_GE(c.nb_bad_adjacency, 1);
  // Three tets on it: 3 and 4 above, 5 below; the two below/above pair linked by hand.
  TetMesh t = testing::make_tet_mesh(pts, {{0, 1, 2, 3}, {0, 1, 2, 5}});
  std::array<int, 4> third{0, 1, 2, 4};
  if (orient3d(t.point(0), t.point(1), t.point(2), t.point(4)) < 0) std::swap(third[2], third[3]);
  t.tets.insert(t.tets.end(), third.begin(), third.end());
  t.adj.insert(t.adj.end(), {-1, -1, -1, -1});
  t.tet_region.push_back(1);
  t.tris.insert(t.tris.end(), {0, 1, 2});
  t.tri_surface.push_back(2);
  c = check_mesh(t);
  EXPECT_FALSE(c.ok);
  bool named = false;
  for (const std::string& p : c.problems)
    named |= p.find("is a face of 3 tets") != std::string::npos;
  EXPECT_TRUE(named);
}

TEST(CheckMesh, SquareOfTwoTrianglesIsValidAndInversionIsDetected) {
  TriMesh2 m = testing::square2();
  EXPECT_TRUE(check_mesh(m).ok);
  EXPECT_EQ(m.adj[m.adj[0 * 3 + 1]], 1);  // edge opposite vertex 1 of t0 is the diagonal
  std::swap(m.tris[1], m.tris[2]);
  build_adjacency2(m);
  EXPECT_EQ(check_mesh(m).nb_inverted, 1);
  EXPECT_EQ(check_mesh(m).nb_bad_adjacency, 0);  // inverted, not also overlapping
}

// The 2D counterparts of the overlap checks: two positive triangles on the same side of their
// common edge, and a boundary edge held by two triangles that are not adjacent.
TEST(CheckMesh, DetectsOverlappingTrianglesIn2D) {
  TriMesh2 m;
  m.xy = {0, 0, 1, 0, 0.3, 1, 0.6, 0.5};
  m.tris = {0, 1, 2, 0, 1, 3};  // both counter-clockwise, 2 and 3 above (0, 1)
  m.tri_region = {1, 1};
  m.edges = {0, 1, 1, 2, 2, 0, 1, 3, 3, 0};
  m.edge_curve = {1, 1, 1, 1, 1};
  m.vclass.assign(4, VertexClass{1, 1});
  build_adjacency2(m);
  MeshCheck c = check_mesh(m);
  EXPECT_FALSE(c.ok);
  EXPECT_GE(c.nb_bad_adjacency, 1);
  bool named = false;
  for (const std::string& p : c.problems) named |= p.find("overlap") != std::string::npos;
  EXPECT_TRUE(named);

  TriMesh2 q = testing::square2();
  for (int& a : q.adj) a = -1;
  q.edges.insert(q.edges.end(), {0, 2});  // the diagonal, held by both triangles, unlinked
  q.edge_curve.push_back(5);
  c = check_mesh(q);
  EXPECT_FALSE(c.ok);
  named = false;
  for (const std::string& p : c.problems)
    named |= p.find("is an edge of 2 triangles that are not adjacent") != std::string::npos;
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace cvtmesh
