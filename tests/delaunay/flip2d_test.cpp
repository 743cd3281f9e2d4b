// The 2D edge flip and its acceptance tests: micro-configurations and a flip pass property.
#include <gtest/gtest.h>

#include <random>

#include "core/delaunay/cdt2d_remesh.h"
#include "core/geometry/predicates.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/face_key.h"
#include "core/swap/flip2d.h"
#include "core/swap/flip2d_delaunay.h"
#include "core/swap/flip2d_pass.h"
#include "core/swap/flip2d_quality.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

int slot_of_edge(const TriMesh2& m, int u, int w) {
  for (int t = 0; t < m.nb_tris(); ++t)
    for (int e = 0; e < 3; ++e)
      if (edge_key(m.tris[3 * t + (e + 1) % 3], m.tris[3 * t + (e + 2) % 3]) == edge_key(u, w))
        return 3 * t + e;
  return -1;
}

bool has_edge(const TriMesh2& m, int u, int w) {
  return slot_of_edge(m, u, w) >= 0;
}

TEST(Flip2d, TwoTrianglesOfTheSquare) {
  TriMesh2 m = testing::square2();  // (0,1,2) and (0,2,3): diagonal 0-2
  ASSERT_TRUE(check_mesh(m).ok);
  const int s = slot_of_edge(m, 0, 2);
  ASSERT_GE(s, 0);
  EXPECT_TRUE(flip2d_possible(m, s));
  ASSERT_TRUE(flip2d(m, s));
  EXPECT_TRUE(check_mesh(m).ok);
  EXPECT_TRUE(has_edge(m, 1, 3));
  EXPECT_FALSE(has_edge(m, 0, 2));
  // Flipping back restores the diagonal 0-2.
  ASSERT_TRUE(flip2d(m, slot_of_edge(m, 1, 3)));
  EXPECT_TRUE(check_mesh(m).ok);
  EXPECT_TRUE(has_edge(m, 0, 2));
}

TEST(Flip2d, RefusesBoundaryAndNonConvex) {
  TriMesh2 m = testing::square2();
  EXPECT_FALSE(flip2d(m, slot_of_edge(m, 0, 1)));  // boundary edge: no neighbour
  // Vertex 3 moved to (1.5, 1.6): (0,2,3) stays counter-clockwise but the quadrilateral
  // 0,1,2,3 has a reflex angle at 2, so the diagonal 1-3 would leave it.
  m.xy[6] = 1.5, m.xy[7] = 1.6;
  ASSERT_TRUE(check_mesh(m).ok);
  const TriMesh2 before = m;
  EXPECT_FALSE(flip2d(m, slot_of_edge(m, 0, 2)));
  EXPECT_EQ(m.tris, before.tris);
  EXPECT_EQ(m.adj, before.adj);
}

TEST(Flip2d, DelaunayAndQualityTestsAreSeparateDecisions) {
  // A thin rhombus split along its long diagonal: neither Delaunay nor good; the flip fixes both.
  TriMesh2 m = testing::square2();
  m.xy = {0, 0, 1, -0.2, 2, 0, 1, 0.2};  // long diagonal 0-2
  ASSERT_TRUE(check_mesh(m).ok);
  const int s = slot_of_edge(m, 0, 2);
  EXPECT_FALSE(is_locally_delaunay2d(m, s));
  EXPECT_TRUE(flip2d_improves_quality(m, s));
  ASSERT_TRUE(flip2d(m, s));
  const int s2 = slot_of_edge(m, 1, 3);
  EXPECT_TRUE(is_locally_delaunay2d(m, s2));
  EXPECT_FALSE(flip2d_improves_quality(m, s2));
  // Cocircular (the unit square): Delaunay both ways, no quality gain either way.
  TriMesh2 q = testing::square2();
  EXPECT_TRUE(is_locally_delaunay2d(q, slot_of_edge(q, 0, 2)));
  EXPECT_FALSE(flip2d_improves_quality(q, slot_of_edge(q, 0, 2)));
}

// A random triangulation of a grid (random diagonals), then a Delaunay flip pass: every
// interior edge locally Delaunay, nothing inverted, constrained edges and vertices untouched.
TEST(Flip2dPass, DelaunayAfterPass) {
  std::mt19937 rng(7);
  const int n = 9;
  TriMesh2 m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool bnd = i == 0 || j == 0 || i == n || j == n;
      const double dx = bnd ? 0 : (rng() % 1000) / 1000.0 * 0.6 - 0.3;
      const double dy = bnd ? 0 : (rng() % 1000) / 1000.0 * 0.6 - 0.3;
      m.xy.push_back(i + dx);
      m.xy.push_back(j + dy);
      m.vclass.push_back(VertexClass{static_cast<std::int8_t>(bnd ? 1 : 2), 1});
    }
  auto id = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (rng() % 2)
        m.tris.insert(m.tris.end(), {a, b, c, a, c, d});
      else
        m.tris.insert(m.tris.end(), {a, b, d, b, c, d});
      m.tri_region.insert(m.tri_region.end(), {1, 1});
    }
  for (int k = 0; k < n; ++k) {
    m.edges.insert(m.edges.end(), {id(k, 0), id(k + 1, 0), id(n, k), id(n, k + 1)});
    m.edges.insert(m.edges.end(), {id(k + 1, n), id(k, n), id(0, k + 1), id(0, k)});
    m.edge_curve.insert(m.edge_curve.end(), {1, 2, 3, 4});
  }
  build_adjacency2(m);
  ASSERT_TRUE(check_mesh(m).ok);
  const std::vector<double> xy = m.xy;
  const long flips = flip2d_pass(m);
  EXPECT_GT(flips, 0);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_EQ(m.xy, xy);
  for (int s = 0; s < 3 * m.nb_tris(); ++s) EXPECT_TRUE(is_locally_delaunay2d(m, s)) << s;
  // A second pass has nothing to do.
  EXPECT_EQ(flip2d_pass(m), 0);
  // A quality pass after it never lowers the minimum quality.
  double qmin = 1;
  for (int t = 0; t < m.nb_tris(); ++t)
    qmin = std::min(qmin, tri_quality(m.point(m.tris[3 * t]), m.point(m.tris[3 * t + 1]),
                                      m.point(m.tris[3 * t + 2]), 2, Measure::kQ));
  flip2d_pass(m, {.criterion = FlipCriterion2d::kQuality});
  EXPECT_TRUE(check_mesh(m).ok);
  double qmin2 = 1;
  for (int t = 0; t < m.nb_tris(); ++t)
    qmin2 = std::min(qmin2, tri_quality(m.point(m.tris[3 * t]), m.point(m.tris[3 * t + 1]),
                                        m.point(m.tris[3 * t + 2]), 2, Measure::kQ));
  EXPECT_GE(qmin2, qmin);
}

}  // namespace
}  // namespace cvtmesh
