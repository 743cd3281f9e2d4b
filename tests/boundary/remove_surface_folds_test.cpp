// Surface fold removal (core/boundary/remove_surface_folds.h) on a hand-made fold: the tet
// (a, b, c, d) under a triangle (a, b, c) in z = 0, and a tet (a, b, c, p) whose apex p lies
// just beyond the edge (a, b), barely above the plane: p's triangle (a, b, p) is turned over
// against (b, c, p) and (c, a, p) (igl_cheburashka's input defect). p is a fold vertex; removed,
// the mesh is the tet (a, b, c, d) with (a, b, c) on the boundary, valid, no triangle turned
// over, p in no element and fixed, its curve edges gone. Without the fold (p above the middle of
// (a, b, c)) nothing is a fold vertex; with a Hausdorff tolerance below p's distance from the
// triangle left, the removal is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/collapse_boundary_edges.h"
#include "core/boundary/discrete_boundary.h"
#include "core/boundary/remove_surface_folds.h"
#include "core/boundary/surface_folds.h"
#include "core/geometry/vec3.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/mesh_data.h"
#include "core/pipeline/optimize.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

constexpr int kP = 4;  // a, b, c, d, p

TetMesh with_apex(double x, double y, double z) {
  return testing::make_tet_mesh(
      {{{0, 0, 0}}, {{1, 0, 0}}, {{0.5, 0.9, 0}}, {{0.5, 0.3, -0.8}}, {{x, y, z}}},
      {{{0, 1, 2, 3}}, {{0, 1, 2, kP}}});
}

TetMesh folded() {
  return with_apex(0.5, -0.01, 5e-4);
}

// The largest turn (degrees) between two boundary triangles across a shared edge.
double sharpest_turn(const TetMesh& m) {
  double worst = 0;
  for (int f = 0; f < m.nb_tris(); ++f)
    for (int g = f + 1; g < m.nb_tris(); ++g) {
      const int* s = &m.tris[3 * f];
      const int* t = &m.tris[3 * g];
      int shared = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) shared += s[i] == t[j];
      if (shared != 2) continue;
      const Vec3 ns = cross(sub(m.point(s[1]), m.point(s[0])), sub(m.point(s[2]), m.point(s[0])));
      const Vec3 nt = cross(sub(m.point(t[1]), m.point(t[0])), sub(m.point(t[2]), m.point(t[0])));
      // Outward-oriented triangles of a closed surface: the turn is the angle between normals.
      worst =
          std::max(worst, std::acos(std::clamp(dot(ns, nt) / (norm(ns) * norm(nt)), -1.0, 1.0)) *
                              180 / 3.14159265358979323846);
    }
  return worst;
}

TEST(RemoveSurfaceFolds, TheFoldVertexGoesAndTheSurfaceIsNoLongerTurnedOver) {
  TetMesh m = folded();
  ASSERT_TRUE(check_mesh(m).ok);
  ASSERT_GT(sharpest_turn(m), 170);
  BoundaryModel b = make_discrete_boundary(m);
  // The fold's two turned-over edges are features: p lies on a curve (igl_cheburashka's case).
  ASSERT_EQ(b.role_of(kP).role, BoundaryRole::kCurve);
  ASSERT_TRUE(is_fold_vertex(m, b, boundary_fans(m), kP));
  for (int v = 0; v < kP; ++v) EXPECT_FALSE(is_fold_vertex(m, b, boundary_fans(m), v)) << v;
  FoldRemovalOptions o;
  o.hausdorff = 0.02;
  const FoldRemovalStats st = remove_surface_folds(m, b, o);
  EXPECT_EQ(st.nb_folds, 1);
  EXPECT_EQ(st.nb_removed, 1);
  const MeshCheck c = check_mesh(m);
  ASSERT_TRUE(c.ok) << c.problems.front();
  ASSERT_EQ(m.nb_tets(), 1);
  ASSERT_EQ(m.nb_tris(), 4);
  for (int x : m.tets) EXPECT_NE(x, kP);
  for (int x : m.tris) EXPECT_NE(x, kP);
  EXPECT_EQ(b.role_of(kP).role, BoundaryRole::kFixed);
  for (const auto& e : b.curve_edges) EXPECT_TRUE(e[0] != kP && e[1] != kP);
  EXPECT_LT(sharpest_turn(m), 150);
}

// Through optimize(): the default run removes the fold and says so (the CLI's "N of them the
// input's surface folds", the scripting result's free_boundary["folds_removed"]).
TEST(RemoveSurfaceFolds, OptimizeCountsTheFoldItRemoved) {
  MeshData d;
  d.dim = 3;
  d.tet = folded();
  OptimizeOptions o;
  o.hausdorff = 0.02;
  const OptimizeResult r = optimize(d, o);
  ASSERT_TRUE(r.boundary_free);
  EXPECT_EQ(r.nb_folds_removed, 1);
  EXPECT_GE(r.nb_boundary_removed, r.nb_folds_removed);
  EXPECT_TRUE(check_mesh(d.tet).ok);
  EXPECT_EQ(d.tet.nb_tets(), 1);
}

TEST(RemoveSurfaceFolds, NoFoldNoRemovalAndTheHausdorffBoundHolds) {
  {
    // p above the middle of (a, b, c): a flat spike, not a fold.
    TetMesh m = with_apex(0.5, 0.3, 5e-4);
    BoundaryModel b = make_discrete_boundary(m);
    EXPECT_FALSE(is_fold_vertex(m, b, boundary_fans(m), kP));
    const TetMesh before = m;
    EXPECT_EQ(remove_surface_folds(m, b).nb_removed, 0);
    EXPECT_EQ(m.tets, before.tets);
    EXPECT_EQ(m.tris, before.tris);
  }
  {
    // p is 0.01 from the triangle that would be left: a tolerance of 0.005 keeps it.
    TetMesh m = folded();
    BoundaryModel b = make_discrete_boundary(m);
    const TetMesh before = m;
    FoldRemovalOptions o;
    o.hausdorff = 0.005;
    const FoldRemovalStats st = remove_surface_folds(m, b, o);
    EXPECT_EQ(st.nb_folds, 1);
    EXPECT_EQ(st.nb_removed, 0);
    EXPECT_EQ(m.tets, before.tets);
    EXPECT_EQ(m.tris, before.tris);
  }
}

}  // namespace
}  // namespace cvtmesh
