// The local repair of a free boundary that ended farther from the reference than its bound.
#include "core/boundary/restore_hausdorff_vertices.h"

#include <gtest/gtest.h>

#include "core/boundary/boundary_hausdorff.h"
#include "core/boundary/discrete_boundary.h"
#include "core/mesh/check_mesh.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

// The cube's six tets, the input triangulation as the reference. One corner pushed out by 0.2
// breaks a bound of 0.05; a tiny move of another corner (1e-3) does not. The repair puts the far
// corner back, keeps the other move, and the distance ends within the bound; a mesh within the
// bound is left alone.
TEST(RestoreHausdorffVertices, PutsTheFarVerticesBackAndKeepsTheRest) {
  const TetMesh input = testing::cube6();
  const BoundaryModel b = make_discrete_boundary(input);
  TetMesh mesh = input;
  int far = -1, near = -1;
  for (int v = 0; v < mesh.nb_vertices(); ++v) {
    const double* p = mesh.point(v);
    if (p[0] == 1 && p[1] == 1 && p[2] == 1) far = v;
    if (p[0] == 0 && p[1] == 0 && p[2] == 0) near = v;
  }
  ASSERT_GE(far, 0);
  ASSERT_GE(near, 0);
  for (int k = 0; k < 3; ++k) mesh.point(far)[k] += 0.2;
  mesh.point(near)[0] -= 1e-3;
  ASSERT_TRUE(check_mesh(mesh).ok);
  const double bound = 0.05;
  ASSERT_GT(boundary_hausdorff(mesh, *b.geometry).value(), bound);
  const RestoreHausdorffStats st = restore_hausdorff_vertices(mesh, input, *b.geometry, bound);
  EXPECT_GT(st.before, bound);
  EXPECT_LE(st.after, bound);
  EXPECT_EQ(st.nb_restored, 1);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(mesh.point(far)[k], input.point(far)[k]);
  EXPECT_EQ(mesh.point(near)[0], input.point(near)[0] - 1e-3);
  EXPECT_TRUE(check_mesh(mesh).ok);
  const TetMesh kept = mesh;
  EXPECT_EQ(restore_hausdorff_vertices(mesh, input, *b.geometry, bound).nb_restored, 0);
  EXPECT_EQ(mesh.xyz, kept.xyz);
}

}  // namespace
}  // namespace cvtmesh
