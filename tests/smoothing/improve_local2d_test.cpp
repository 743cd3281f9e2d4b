// The never-worse local improvement of planar triangle meshes (improve_local2d.h): on a grid
// whose interior vertices are pushed off, the mesh stays valid, no quality row falls, the average
// Q rises, the boundary, the constrained edges and the fixed vertices are kept.
#include "core/smoothing/improve_local2d.h"

#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "core/mesh/check_mesh.h"
#include "core/quality/quality_stats.h"
#include "core/quality/worse_than.h"

namespace cvtmesh {
namespace {

// The (n+1) x (n+1) grid on [0, n]^2, two triangles per cell (diagonals alternating so that a
// flip can matter), interior vertices moved by up to `amount` (a fixed pattern); the boundary
// edges constrained on curve 1, and the row j = n/2 of interior edges constrained on curve 2.
TriMesh2 pushed_grid(int n, double amount) {
  TriMesh2 m;
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool inside = i > 0 && j > 0 && i < n && j < n;
      const double dx = inside ? amount * (((i * 7 + j * 3) % 5) - 2) / 2.0 : 0;
      const double dy = inside && j != n / 2 ? amount * (((i * 3 + j * 5) % 7) - 3) / 3.0 : 0;
      m.xy.insert(m.xy.end(), {i + dx, j + dy});
      m.vclass.push_back(inside ? VertexClass{2, 1} : VertexClass{1, 1});
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2)
        m.tris.insert(m.tris.end(), {a, b, c, a, c, d});
      else
        m.tris.insert(m.tris.end(), {a, b, d, b, c, d});
      m.tri_region.insert(m.tri_region.end(), {1, 1});
    }
  for (int k = 0; k < n; ++k) {
    for (auto [u, v] : {std::pair{id(k, 0), id(k + 1, 0)},
                        {id(n, k), id(n, k + 1)},
                        {id(k + 1, n), id(k, n)},
                        {id(0, k + 1), id(0, k)}}) {
      m.edges.insert(m.edges.end(), {u, v});
      m.edge_curve.push_back(1);
    }
    m.edges.insert(m.edges.end(), {id(k, n / 2), id(k + 1, n / 2)});
    m.edge_curve.push_back(2);
  }
  build_adjacency2(m);
  return m;
}

std::set<std::pair<int, int>> edge_set(const TriMesh2& m) {
  std::set<std::pair<int, int>> s;
  for (int t = 0; t < m.nb_tris(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = m.tris[3 * t + k], b = m.tris[3 * t + (k + 1) % 3];
      s.insert({std::min(a, b), std::max(a, b)});
    }
  return s;
}

TEST(ImproveLocal2d, NeverWorseAndAverageUpOnAPushedGrid) {
  TriMesh2 m = pushed_grid(8, 0.3);
  ASSERT_TRUE(check_mesh(m).ok);
  const TriMesh2 input = m;
  const QualityStats before = quality_stats(m, "before");
  std::vector<char> fixed(m.nb_vertices(), 0);
  fixed[3 * 9 + 3] = 1;  // vertex (3, 3)
  const ImproveLocal2dStats st = improve_local2d(m, fixed);
  const MeshCheck c = check_mesh(m);
  ASSERT_TRUE(c.ok) << c.problems.front();
  const QualityStats after = quality_stats(m, "after");
  EXPECT_EQ(worse_than(after, before), "");
  EXPECT_GT(st.nb_moves, 0);
  EXPECT_GT(after.q_avg, before.q_avg + 1e-3);
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim != 2 || fixed[v] || v / 9 == 4) {  // boundary, fixed, on curve 2
      EXPECT_EQ(m.xy[2 * v], input.xy[2 * v]) << v;
      EXPECT_EQ(m.xy[2 * v + 1], input.xy[2 * v + 1]) << v;
    }
  const auto edges = edge_set(m);
  for (int e = 0; e < m.nb_edges(); ++e) {
    const int a = m.edges[2 * e], b = m.edges[2 * e + 1];
    EXPECT_TRUE(edges.count({std::min(a, b), std::max(a, b)})) << "constrained edge " << e;
  }
}

// A mesh no local operation can improve (a grid of right isosceles triangles: every triangle at
// the minimum Q, every flip gives the same two triangles) is left as it is.
TEST(ImproveLocal2d, LeavesAnOptimalGridAlone) {
  TriMesh2 m = pushed_grid(4, 0.0);
  const TriMesh2 input = m;
  const ImproveLocal2dStats st = improve_local2d(m);
  EXPECT_EQ(st.nb_moves + st.nb_flips, 0);
  EXPECT_EQ(m.xy, input.xy);
  EXPECT_EQ(m.tris, input.tris);
}

}  // namespace
}  // namespace cvtmesh
