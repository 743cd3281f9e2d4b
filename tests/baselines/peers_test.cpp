// The peer optimizers of compare and bench (issue 17): Netgen's volume optimizer and CGAL's
// tetrahedral remeshing, run on a Gmsh Init, must return a valid mesh with the input's boundary
// triangles (verify_peer), and improve the Init's worst element (both are optimizers: a result
// worse than the input at its worst tet would mean the transfer broke it).
#include <gtest/gtest.h>

#include "bench/baselines/cgal_mesh3.h"
#include "bench/baselines/cgal_remesh.h"
#include "bench/baselines/netgen_optimize.h"
#include "bench/baselines/verify_peer.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/verify_mesh.h"
#include "core/quality/quality_stats.h"
#include "core/util/error.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

TEST(Peers, NetgenKeepsTheBoundaryAndImprovesTheInit) {
  const MeshData init = testing::cube_sphere(0.2, 0.15);
  TetMesh m = init.tet;
  const NetgenResult r = netgen_optimize(m);
  // scripts/setup.sh installs python3-netgen: a missing Netgen is a set-up error here.
  ASSERT_TRUE(r.available) << r.message;
  EXPECT_TRUE(check_mesh(m).ok);
  EXPECT_NO_THROW(verify_peer(init.tet, m, "Netgen"));
  EXPECT_GT(r.seconds, 0.0);
  EXPECT_GT(quality_stats(m, "").q_min, quality_stats(init.tet, "").q_min);
}

TEST(Peers, CgalKeepsTheBoundaryAndImprovesTheInit) {
  const MeshData init = testing::cube_sphere(0.2, 0.15);
  TetMesh m = init.tet;
  cgal_remesh(m);
  EXPECT_TRUE(check_mesh(m).ok);
  EXPECT_NO_THROW(verify_peer(init.tet, m, "CGAL"));
  EXPECT_GT(quality_stats(m, "").q_min, quality_stats(init.tet, "").q_min);
}

// A node of no tet (Gmsh keeps the nodes of a model's points, curves and loose surfaces: its
// tutorials t2, t3, t5 and t19) is left out of CGAL's triangulation: it has no incident cell
// there, and CGAL's remeshing crashed walking around it (compare died with SIGSEGV).
TEST(Peers, CgalRemeshingIgnoresNodesOfNoTet) {
  MeshData init = testing::cube_sphere(0.2, 0.15);
  TetMesh& in = init.tet;
  const int v = in.nb_vertices();
  in.xyz.insert(in.xyz.end(), {2.0, 2.0, 2.0});
  in.vclass.push_back(in.vclass[0]);
  if (!in.node_tags.empty()) in.node_tags.push_back(in.node_tags.back() + 1000);
  ASSERT_EQ(in.nb_vertices(), v + 1);
  TetMesh m = in;
  cgal_remesh(m);
  EXPECT_TRUE(check_mesh(m).ok);
  EXPECT_NO_THROW(verify_peer(in, m, "CGAL"));
  EXPECT_GT(quality_stats(m, "").q_min, quality_stats(in, "").q_min);
}

// Mesh_3 makes a new mesh of the same domain: valid, one region, and its volume that of the input
// to within the surface approximation (facet_distance = size / 10).
TEST(Peers, CgalMesh3MeshesTheSameDomain) {
  const MeshData init = testing::cube_sphere(0.2, 0.15);
  TetMesh m = init.tet;
  cgal_mesh3(m);
  EXPECT_TRUE(check_mesh(m).ok);
  ASSERT_GT(m.nb_tets(), 0);
  const auto v0 = region_volumes(init.tet), v1 = region_volumes(m);
  ASSERT_EQ(v0.size(), 1u);
  ASSERT_EQ(v1.size(), 1u);
  EXPECT_NEAR(v1[0].second, v0[0].second, 0.02 * v0[0].second);
}

TEST(Peers, VerifyPeerRefusesAMovedBoundaryVertex) {
  const MeshData init = testing::cube_sphere(0.2, 0.15);
  TetMesh m = init.tet;
  int v = 0;
  while (m.vclass[v].dim == 3) ++v;
  m.xyz[3 * v] += 1e-9;
  EXPECT_THROW(verify_peer(init.tet, m, "test"), InvariantError);
}

}  // namespace
}  // namespace cvtmesh
