// The local copy's commit: an edit that lost one of the copy's constrained triangles is refused.
#include "core/swap/local_mesh.h"

#include <gtest/gtest.h>

#include "core/mesh/check_mesh.h"
#include "core/swap/constrained_faces.h"
#include "core/swap/insert_vertex.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

// The cube's six tets copied whole; "after" inserts a point off the diagonal into all of them (a
// convex cavity): without a constrained inner face the commit goes through, with one (an embedded
// surface's triangle, which the insertion deletes) it is refused and the mesh is unchanged.
TEST(CommitLocalMesh, RefusesAnEditThatLosesAConstrainedTriangle) {
  for (const bool embedded : {false, true}) {
    TetMesh m = testing::cube6();
    if (embedded) {
      int f0 = 0;
      while (m.adj[f0] < 0) ++f0;
      for (int k = 0; k < 3; ++k) m.tris.push_back(m.tets[kTetFace[f0][k]]);
      m.tri_surface.push_back(2);
    }
    const ConstrainedFaces constrained = constrained_faces(m);
    std::vector<int> all;
    for (int t = 0; t < m.nb_tets(); ++t) all.push_back(t);
    const LocalMesh local = extract_local_mesh(m, constrained, all);
    TetMesh after = local.mesh;
    const double p[3] = {0.55, 0.5, 0.4};
    std::vector<int> cavity;
    for (int t = 0; t < after.nb_tets(); ++t) cavity.push_back(t);
    SwapPlan plan = plan_insert_vertex(after, cavity, p);
    ASSERT_EQ(plan.status, SwapStatus::kOk);
    insert_vertex(after, plan, p);
    const TetMesh before = m;
    std::vector<int> free_slots;
    EXPECT_EQ(commit_local_mesh(m, local, after, &free_slots), !embedded) << embedded;
    if (embedded) {
      EXPECT_EQ(m.tets, before.tets);
      EXPECT_EQ(m.xyz, before.xyz);
    } else {
      EXPECT_EQ(m.nb_vertices(), before.nb_vertices() + 1);
    }
    EXPECT_TRUE(check_mesh(m).ok);
  }
}

}  // namespace
}  // namespace cvtmesh
