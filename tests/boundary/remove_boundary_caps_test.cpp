// Boundary cap removal (the one-tet surface flip) on a hand-made configuration: a thin tet (a, b,
// c, d) lying on the surface over the two tets (a, c, d, e), (b, c, d, e). Removed, the surface
// edge (a, b) becomes (c, d): the mesh is valid, no vertex moves or leaves the boundary, the
// surface keeps its number of triangles, its tag, its vertices and its topology (a closed
// manifold, same Euler characteristic), and the local minimum rises. Refused (mesh unchanged)
// when the new triangles would leave the Hausdorff tolerance or the surface is not flat enough.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "core/boundary/discrete_boundary.h"
#include "core/boundary/remove_boundary_caps.h"
#include "core/mesh/build_adjacency.h"
#include "core/mesh/check_mesh.h"
#include "core/quality/quality.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

constexpr double kEps = 0.05;

TetMesh capped() {
  // a, b raised by kEps above the plane z = 0 of c, d; e below.
  return testing::make_tet_mesh(
      {{{0, 0, kEps}}, {{1, 1, kEps}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0.5, 0.5, -1}}},
      {{{0, 1, 2, 3}}, {{0, 2, 3, 4}}, {{1, 2, 3, 4}}});
}

BoundaryModel smooth_model(const TetMesh& m) {
  BoundaryModelOptions o;
  o.feature_angle = 179;  // one smooth patch: every vertex a surface vertex
  return make_discrete_boundary(m, o);
}

// min over the tets' min(Q, min dihedral / 60) and the boundary triangles' Q.
double local_min(const TetMesh& m) {
  double q = 2;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* w = &m.tets[4 * static_cast<std::size_t>(t)];
    const double *a = m.point(w[0]), *b = m.point(w[1]), *c = m.point(w[2]), *d = m.point(w[3]);
    q = std::min({q, tet_quality(a, b, c, d, Measure::kQ),
                  tet_quality(a, b, c, d, Measure::kMinAngle) / 60});
  }
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* w = &m.tris[3 * static_cast<std::size_t>(f)];
    q = std::min(q, tri_quality(m.point(w[0]), m.point(w[1]), m.point(w[2]), 3, Measure::kQ));
  }
  return q;
}

// Every boundary edge on exactly two triangles; returns V - E + F of the boundary.
int surface_euler(const TetMesh& m) {
  std::map<std::pair<int, int>, int> edges;
  std::set<int> verts;
  for (int f = 0; f < m.nb_tris(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int x = m.tris[3 * f + k], y = m.tris[3 * f + (k + 1) % 3];
      ++edges[{std::min(x, y), std::max(x, y)}];
      verts.insert(x);
    }
  for (const auto& [e, n] : edges) EXPECT_EQ(n, 2) << e.first << "-" << e.second;
  return static_cast<int>(verts.size()) - static_cast<int>(edges.size()) + m.nb_tris();
}

TEST(RemoveBoundaryCaps, TheCapGoesAndTheSurfaceEdgeFlips) {
  TetMesh m = capped();
  ASSERT_TRUE(check_mesh(m).ok);
  const TetMesh before = m;
  const BoundaryModel b = smooth_model(m);
  ASSERT_EQ(b.nb_surface_vertices, 5);
  const double min_before = local_min(m);
  const int euler_before = surface_euler(m);
  const CapRemovalStats st = remove_boundary_caps(m, b);
  EXPECT_EQ(st.nb_removed, 1);
  ASSERT_TRUE(check_mesh(m).ok) << (check_mesh(m).problems.empty() ? ""
                                                                   : check_mesh(m).problems[0]);
  EXPECT_EQ(m.nb_tets(), 2);
  EXPECT_EQ(m.nb_tris(), before.nb_tris());
  EXPECT_EQ(m.tri_surface, before.tri_surface);
  EXPECT_EQ(m.xyz, before.xyz);
  EXPECT_EQ(surface_euler(m), euler_before);
  // The new boundary triangles are (a, c, d) and (b, c, d); (a, b) is no edge any more.
  std::set<std::set<int>> tris;
  for (int f = 0; f < m.nb_tris(); ++f)
    tris.insert({m.tris[3 * f], m.tris[3 * f + 1], m.tris[3 * f + 2]});
  EXPECT_TRUE(tris.count({0, 2, 3}));
  EXPECT_TRUE(tris.count({1, 2, 3}));
  EXPECT_FALSE(tris.count({0, 1, 2}));
  // Every vertex still on the boundary.
  std::set<int> on;
  for (int v : m.tris) on.insert(v);
  EXPECT_EQ(on.size(), 5u);
  EXPECT_GT(local_min(m), min_before + 0.1);
}

TEST(RemoveBoundaryCaps, RefusedOutsideTheHausdorffToleranceOrWhenNotFlat) {
  for (int k = 0; k < 2; ++k) {
    TetMesh m = capped();
    const TetMesh before = m;
    const BoundaryModel b = smooth_model(m);
    build_adjacency(m);
    const VertexTets star = vertex_tets(m);
    const BoundaryFans fans = boundary_fans(m);
    CapRemovalOptions o;
    if (k == 0) o.hausdorff = kEps / 100;  // the new triangles lie ~kEps below the old ones
    if (k == 1) o.flat_angle = 1;          // the old triangles turn by a few degrees
    CapPlan plan;
    EXPECT_EQ(plan_cap_removal(m, b, star, fans, 0, o, plan),
              k == 0 ? CapCheck::kHausdorff : CapCheck::kNotFlat);
    EXPECT_EQ(remove_boundary_caps(m, b, o).nb_removed, 0);
    EXPECT_EQ(m.tets, before.tets);
    EXPECT_EQ(m.tris, before.tris);
  }
}

}  // namespace
}  // namespace cvtmesh
