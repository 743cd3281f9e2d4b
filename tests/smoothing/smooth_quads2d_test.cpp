// The quadrangle smoothing of planar hybrid meshes (smooth_quads2d.h): on a grid of quadrangles
// with its interior vertices pushed off, and on quadrangles next to triangles sharing interior
// vertices, the minimum scaled Jacobian and the triangles' minimum Q never fall, every element
// stays positive (quadrangles strictly convex), the boundary and the area are kept.
#include "core/smoothing/smooth_quads2d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/mesh/check_mesh.h"
#include "core/mesh/check_quads2d.h"
#include "core/mesh/constrain_kept_quad_edges.h"
#include "core/mesh/kept_quads.h"
#include "core/quality/quad_scaled_jacobian.h"
#include "core/quality/quality.h"

namespace cvtmesh {
namespace {

// The (n+1) x (n+1) grid on [0, n]^2; cells of column < quad_columns are quadrangles, the others
// two triangles each. Boundary vertices on curve 1 (lines where a triangle has the edge).
TriMesh2 grid(int n, int quad_columns) {
  TriMesh2 m;
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      m.xy.insert(m.xy.end(), {double(i), double(j)});
      const bool boundary = i == 0 || j == 0 || i == n || j == n;
      m.vclass.push_back({static_cast<std::int8_t>(boundary ? 1 : 2), 1});
    }
  ElementBlock quads;
  quads.dim = 2, quads.entity = 1, quads.gmsh_type = kGmshQuad;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (i < quad_columns) {
        quads.nodes.insert(quads.nodes.end(), {a, b, c, d});
        quads.tags.push_back(quads.tags.size() + 1);
      } else {
        m.tris.insert(m.tris.end(), {a, b, c, a, c, d});
        m.tri_region.insert(m.tri_region.end(), {1, 1});
      }
    }
  m.model.extra.push_back(quads);
  for (int k = 0; k < n; ++k)
    for (auto [a, b] : {std::pair{id(k, 0), id(k + 1, 0)}, std::pair{id(n, k), id(n, k + 1)},
                        std::pair{id(k + 1, n), id(k, n)}, std::pair{id(0, k + 1), id(0, k)}}) {
      // The column of the cell holding the edge: a quadrangle's edge gets no line.
      const int column = std::min(static_cast<int>(0.5 * (m.xy[2 * a] + m.xy[2 * b])), n - 1);
      if (column < quad_columns) continue;
      m.edges.insert(m.edges.end(), {a, b});
      m.edge_curve.push_back(1);
    }
  build_adjacency2(m);
  constrain_kept_quad_edges(m);
  return m;
}

struct Extremes {
  double sj_min = std::numeric_limits<double>::infinity(), tq_min = 2, area = 0;
};
Extremes extremes(const TriMesh2& m) {
  Extremes e;
  const KeptQuads q = kept_quads(m);
  for (int k = 0; k < q.nb_quads(); ++k) {
    const int* v = &q.quads[4 * k];
    e.sj_min = std::min(
        e.sj_min, quad_scaled_jacobian(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])));
    for (int t : {0, 2}) {
      const double *a = m.point(v[t]), *b = m.point(v[t + 1]), *c = m.point(v[(t + 2) % 4]);
      e.area += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    }
  }
  for (int t = 0; t < m.nb_tris(); ++t) {
    const double *a = m.point(m.tris[3 * t]), *b = m.point(m.tris[3 * t + 1]),
                 *c = m.point(m.tris[3 * t + 2]);
    e.tq_min = std::min(e.tq_min, tri_quality(a, b, c, 2, Measure::kQ));
    e.area += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
  }
  return e;
}

void expect_boundary_kept(const TriMesh2& before, const TriMesh2& after) {
  for (int v = 0; v < before.nb_vertices(); ++v)
    if (before.vclass[v].dim < 2) {
      EXPECT_EQ(before.point(v)[0], after.point(v)[0]) << v;
      EXPECT_EQ(before.point(v)[1], after.point(v)[1]) << v;
    }
}

TEST(SmoothQuads2d, APerturbedGridOfQuadranglesGoesBackTowardsSquares) {
  TriMesh2 m = grid(4, 4);
  ASSERT_EQ(m.nb_tris(), 0);
  // Interior vertices pushed off by up to 0.35 (every quadrangle still convex).
  const double push[9][2] = {{0.3, 0.2},   {-0.35, 0.1}, {0.2, -0.3}, {-0.1, 0.3}, {0.25, 0.25},
                             {-0.3, -0.2}, {0.1, -0.35}, {0.35, 0},   {-0.2, 0.3}};
  int k = 0;
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim == 2) m.point(v)[0] += push[k][0], m.point(v)[1] += push[k++][1];
  ASSERT_EQ(k, 9);
  ASSERT_TRUE(check_quads2d(m).ok());
  const TriMesh2 before = m;
  const Extremes e0 = extremes(m);
  // The compass search everywhere (by default only where a star is below 0.9).
  SmoothQuads2dOptions o;
  o.compass_below = 1.01;
  const SmoothQuads2dStats st = smooth_quads2d(m, o);
  EXPECT_EQ(st.nb_free, 9);
  EXPECT_GT(st.nb_moves, 0);
  const Extremes e1 = extremes(m);
  // The unperturbed grid's squares are the optimum (scaled Jacobian 1): the smoothing gets most
  // of the way back.
  EXPECT_GT(e1.sj_min, e0.sj_min);
  EXPECT_GT(e1.sj_min, 0.95);
  EXPECT_TRUE(check_quads2d(m).ok());
  EXPECT_NEAR(e1.area, 16.0, 1e-12);
  expect_boundary_kept(before, m);
}

TEST(SmoothQuads2d, AVertexSharedByTrianglesAndQuadranglesChecksBothSides) {
  // Columns 0-1 quadrangles, 2-3 triangles: the vertices at x = 2 inside are shared.
  TriMesh2 m = grid(4, 2);
  ASSERT_TRUE(check_mesh(m).ok);
  int shared = -1;
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.point(v)[0] == 2 && m.point(v)[1] == 2) shared = v;
  ASSERT_GE(shared, 0);
  m.point(shared)[0] -= 0.4;  // squeezes the quadrangles, stretches the triangles
  m.point(shared)[1] += 0.3;
  ASSERT_TRUE(check_mesh(m).ok);
  ASSERT_TRUE(check_quads2d(m).ok());
  const TriMesh2 before = m;
  const Extremes e0 = extremes(m);
  smooth_quads2d(m);
  const Extremes e1 = extremes(m);
  EXPECT_TRUE(check_mesh(m).ok);  // every triangle positive, constrained edges held
  EXPECT_TRUE(check_quads2d(m).ok());
  EXPECT_GE(e1.sj_min, e0.sj_min);
  EXPECT_GE(e1.tq_min, e0.tq_min);
  EXPECT_NEAR(e1.area, e0.area, 1e-12 * e0.area);
  // The shared vertex moved back towards x = 2 (both sides improve there).
  EXPECT_GT(m.point(shared)[0], before.point(shared)[0]);
  expect_boundary_kept(before, m);
}

TEST(SmoothQuads2d, WithoutQuadranglesNothingMoves) {
  TriMesh2 m = grid(3, 0);
  const TriMesh2 before = m;
  const SmoothQuads2dStats st = smooth_quads2d(m);
  EXPECT_EQ(st.nb_moves, 0);
  EXPECT_EQ(m.xy, before.xy);
}

}  // namespace
}  // namespace cvtmesh
