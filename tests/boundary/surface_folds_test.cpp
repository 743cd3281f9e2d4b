// Surface folds (core/boundary/surface_folds.h): a boundary vertex move that turns a triangle
// over, or sharpens a feature past kFoldFloor, is a fold; a small move on a flat fan is not. A
// surface flip across a non-convex quad folds; across a convex one it does not. The flip and the
// cap removal keep every boundary triangle's turning sense (a Gmsh file's surface normals), for
// triangles written either way round.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/discrete_boundary.h"
#include "core/boundary/flip_boundary_edges.h"
#include "core/boundary/remove_boundary_caps.h"
#include "core/boundary/surface_folds.h"
#include "core/geometry/predicates.h"
#include "core/mesh/check_mesh.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A hexagonal fan: vertex 0 at the origin, 1..6 on the unit circle in z = 0, apex 7 at depth h.
TetMesh fan(double h = 1) {
  std::vector<std::array<double, 3>> p{{0, 0, 0}};
  for (int i = 0; i < 6; ++i) p.push_back({std::cos(i * kPi / 3), std::sin(i * kPi / 3), 0});
  p.push_back({0, 0, -h});
  std::vector<std::array<int, 4>> t;
  for (int i = 0; i < 6; ++i) t.push_back({0, 1 + i, 1 + (i + 1) % 6, 7});
  return testing::make_tet_mesh(p, t);
}

// For every boundary triangle, whether its apex (the fourth vertex of its tet) lies on the
// positive side of it.
std::vector<int> turning_senses(const TetMesh& m) {
  std::vector<int> s;
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* w = &m.tris[3 * f];
    for (int t = 0; t < m.nb_tets(); ++t) {
      const int* v = &m.tets[4 * t];
      if (v[0] < 0) continue;
      int shared = 0, apex = -1;
      for (int k = 0; k < 4; ++k) {
        const bool on = v[k] == w[0] || v[k] == w[1] || v[k] == w[2];
        shared += on;
        if (!on) apex = v[k];
      }
      if (shared == 3)
        s.push_back(orient3d(m.point(w[0]), m.point(w[1]), m.point(w[2]), m.point(apex)) > 0);
    }
  }
  return s;
}

TEST(SurfaceFolds, AMoveThatTurnsATriangleOverFoldsASmallOneDoesNot) {
  const TetMesh m = fan();
  const BoundaryFans fans = boundary_fans(m);
  const double small[3] = {0.1, 0.05, 0.02}, over[3] = {1.6, 0.1, 0};
  EXPECT_FALSE(move_folds_surface(m, fans, 0, small));
  EXPECT_TRUE(move_folds_surface(m, fans, 0, over));
}

TEST(SurfaceFolds, AFeatureMayGetFlatterButNotSharper) {
  // With the apex at depth 0.2 the rim edges (i, i+1) turn by about 167 degrees (cos -0.97 <
  // kFoldFloor) between the top and the side triangles: raising vertex 0 flattens them, lowering
  // it sharpens them. With the apex at depth 1 (135 degrees, above the floor) both are free.
  const TetMesh m = fan(0.2);
  const BoundaryFans fans = boundary_fans(m);
  const double up[3] = {0, 0, 0.05}, down[3] = {0, 0, -0.05};
  EXPECT_FALSE(move_folds_surface(m, fans, 0, up));
  EXPECT_TRUE(move_folds_surface(m, fans, 0, down));
  const TetMesh deep = fan(1);
  const BoundaryFans deep_fans = boundary_fans(deep);
  EXPECT_FALSE(move_folds_surface(deep, deep_fans, 0, up));
  EXPECT_FALSE(move_folds_surface(deep, deep_fans, 0, down));
}

// Two tets on the edge (a, b) = (0, 1) under the surface triangles (0, 1, 2) and (0, 1, 3),
// apex 4 below.
TetMesh quad(const std::array<double, 3>& d) {
  return testing::make_tet_mesh({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, d, {0.5, 0, -1}},
                                {{0, 1, 2, 4}, {0, 1, 3, 4}});
}

int tri_with(const TetMesh& m, int x, int y, int z) {
  for (int f = 0; f < m.nb_tris(); ++f) {
    int n = 0;
    for (int k = 0; k < 3; ++k)
      n += m.tris[3 * f + k] == x || m.tris[3 * f + k] == y || m.tris[3 * f + k] == z;
    if (n == 3) return f;
  }
  return -1;
}

TEST(SurfaceFolds, AFlipAcrossANonConvexQuadFoldsAcrossAConvexOneNot) {
  const double pair_floor = std::cos(40 * kPi / 180);
  const TetMesh convex = quad({0.5, -1, 0});
  const TetMesh concave = quad({1.6, -0.2, 0});  // (2, 3) passes outside the quad, beyond b
  for (const TetMesh* m : {&convex, &concave}) {
    const BoundaryFans fans = boundary_fans(*m);
    const int f1 = tri_with(*m, 0, 1, 2), f2 = tri_with(*m, 0, 1, 3);
    ASSERT_GE(f1, 0);
    ASSERT_GE(f2, 0);
    EXPECT_EQ(flip_folds_surface(*m, fans, f1, f2, 0, 1, 2, 3, pair_floor), m == &concave);
  }
}

TEST(SurfaceFolds, TheCapRemovalKeepsEachTrianglesTurningSense) {
  for (const bool reversed : {false, true}) {
    // The cap of remove_boundary_caps_test: a thin tet over two others.
    TetMesh m =
        testing::make_tet_mesh({{0, 0, 0.05}, {1, 1, 0.05}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, -1}},
                               {{0, 1, 2, 3}, {0, 2, 3, 4}, {1, 2, 3, 4}});
    if (reversed)
      for (int f = 0; f < m.nb_tris(); ++f) std::swap(m.tris[3 * f + 1], m.tris[3 * f + 2]);
    const std::vector<int> before = turning_senses(m);
    BoundaryModelOptions bo;
    bo.feature_angle = 179;
    const BoundaryModel b = make_discrete_boundary(m, bo);
    ASSERT_EQ(remove_boundary_caps(m, b).nb_removed, 1);
    ASSERT_TRUE(check_mesh(m).ok);
    const std::vector<int> after = turning_senses(m);
    ASSERT_EQ(after.size(), before.size());
    for (std::size_t i = 0; i < after.size(); ++i) {
      ASSERT_EQ(before[i], before[0]);
      EXPECT_EQ(after[i], before[0]) << i;
    }
  }
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

// The Delaunay tetrahedralization of random points on and in a cube, its hull flipped freely (any
// turn up to 179 degrees, no Hausdorff bound): every flip a valid retriangulation (no tets on the
// same side of a face: the cone over the ring's polygon turns one way) that keeps the triangles'
// senses.
TEST(FlipBoundaryEdges, RandomHullsStayValidAndKeepTheirTrianglesSenses) {
  long flipped = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    // The cube's corners, 80 points on its faces, 30 inside: poor hull triangles, flat faces.
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> xyz;
    for (int c = 0; c < 8; ++c)
      xyz.insert(xyz.end(), {double(c & 1), double(c >> 1 & 1), double(c >> 2)});
    for (int i = 0; i < 80; ++i) {
      const int axis = i % 3;
      double p[3] = {u(rng), u(rng), u(rng)};
      p[axis] = (i / 3) % 2;
      xyz.insert(xyz.end(), p, p + 3);
    }
    for (int i = 0; i < 30; ++i) xyz.insert(xyz.end(), {u(rng), u(rng), u(rng)});
    TetMesh m = testing::delaunay_of_points(xyz);
    ASSERT_TRUE(check_mesh(m).ok);
    const std::vector<int> before = turning_senses(m);
    BoundaryModelOptions bo;
    bo.feature_angle = 179;
    const BoundaryModel b = make_discrete_boundary(m, bo);
    BoundaryFlipOptions fo;
    fo.flat_angle = 179;
    fo.tri_below = 1;
    flipped += flip_boundary_edges(m, b, fo).nb_flipped;
    const MeshCheck c = check_mesh(m);
    ASSERT_TRUE(c.ok) << "seed " << seed << ": " << c.problems[0];
    const std::vector<int> after = turning_senses(m);
    ASSERT_EQ(after.size(), before.size());
    for (std::size_t i = 0; i < after.size(); ++i) ASSERT_EQ(after[i], before[0]) << seed;
  }
  EXPECT_GT(flipped, 100) << flipped;
}

}  // namespace
}  // namespace cvtmesh
