#include "core/delaunay/relocate_vertices3.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/cvt/cell_mesh.h"
#include "core/cvt/lloyd3.h"
#include "core/delaunay/delaunay3.h"
#include "core/delaunay/restore_delaunay3.h"
#include "core/geometry/predicates.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/verify_mesh.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

// The unconstrained faces of m that are not locally Delaunay (sorted vertex ids).
std::vector<FaceKey> non_delaunay_face_keys(const TetMesh& m) {
  const ConstrainedFaces cf = constrained_faces(m);
  std::vector<FaceKey> out;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] < 0) continue;
    for (int f = 0; f < 4; ++f) {
      const int o = m.adj[4 * t + f];
      if (o < 0 || cf.count(face_key(v[kTetFace[f][0]], v[kTetFace[f][1]], v[kTetFace[f][2]])))
        continue;
      const int e = m.tets[4 * (o / 4) + o % 4];
      if (insphere(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]), m.point(e)) > 0)
        out.push_back(face_key(v[kTetFace[f][0]], v[kTetFace[f][1]], v[kTetFace[f][2]]));
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

int non_delaunay_faces(const TetMesh& m) {
  return static_cast<int>(non_delaunay_face_keys(m).size());
}

// Random moves of the free vertices by up to `amount` x h: the result is at the targets,
// constrained Delaunay, valid, with the same boundary and volume. Whether or not, every face left
// non-Delaunay is listed in stuck_faces, and the cells' test of the listed faces alone
// (prepare_cell_mesh with them as suspects) marks the same tets as testing every face.
// Returns the number of faces left non-Delaunay.
int relocate_randomly(double amount, unsigned seed, bool expect_ok) {
  MeshData d = testing::cube_sphere(0.12, 0.1);
  TetMesh& m = d.tet;
  Delaunay3::create("tetgen")->retetrahedralize(m);
  const TetMesh before = m;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> target = m.xyz;
  for (int v = 0; v < m.nb_vertices(); ++v) {
    if (m.vclass[v].dim != 3) continue;
    for (int k = 0; k < 3; ++k) target[3 * v + k] += amount * 0.12 * u(rng);
    for (int k = 0; k < 3; ++k) target[3 * v + k] = std::clamp(target[3 * v + k], 0.01, 0.99);
  }
  const RelocateStats st = relocate_vertices(m, constrained_faces(m), target);
  SCOPED_TRACE("amount " + std::to_string(amount) + " rounds " + std::to_string(st.rounds) +
               " flips " + std::to_string(st.nb_flips) + " pending " +
               std::to_string(st.nb_pending));
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.ok ? "" : c.problems.front());
  EXPECT_NO_THROW(verify_optimized(before, m));  // boundary, fixed vertices, volumes
  if (expect_ok) EXPECT_TRUE(st.ok);
  if (st.ok) {
    EXPECT_EQ(m.xyz, target);
    EXPECT_EQ(non_delaunay_faces(m), 0);
    EXPECT_GT(st.nb_flips, 0);
  }
  const std::vector<FaceKey> left = non_delaunay_face_keys(m);
  for (const FaceKey& k : left)
    EXPECT_TRUE(std::find(st.stuck_faces.begin(), st.stuck_faces.end(), k) != st.stuck_faces.end())
        << k[0] << " " << k[1] << " " << k[2];
  CellMesh all, listed;
  prepare_cell_mesh(m, nullptr, false, all);
  prepare_cell_mesh(m, nullptr, true, listed, &st.stuck_faces);
  EXPECT_EQ(listed.dual_ok, all.dual_ok);
  return static_cast<int>(left.size());
}

TEST(RelocateVertices3, SmallMovesEndAtTheTargetsAndDelaunay) {
  relocate_randomly(0.05, 1, /*expect_ok=*/true);
  relocate_randomly(0.15, 2, /*expect_ok=*/true);
}

// Moves of the order of the edge length tangle stars: whatever happens, the mesh stays valid.
TEST(RelocateVertices3, LargeMovesKeepTheMeshValid) {
  const int left = relocate_randomly(0.6, 3, /*expect_ok=*/false) +
                   relocate_randomly(1.0, 4, /*expect_ok=*/false);
  EXPECT_GT(left, 0);  // the listing above was exercised
}

TEST(RestoreDelaunay3, RefusesAnInvertedMeshWithoutChangingIt) {
  MeshData d = testing::cube_sphere(0.15, 0.12);
  TetMesh m = d.tet;
  // Push an interior vertex far through its star.
  int v = 0;
  while (m.vclass[v].dim != 3) ++v;
  m.xyz[3 * v] += 0.5;
  const TetMesh moved = m;
  const RestoreDelaunayStats st = restore_delaunay_by_flips(m, constrained_faces(m));
  EXPECT_TRUE(st.inverted);
  EXPECT_FALSE(st.ok);
  EXPECT_EQ(m.tets, moved.tets);
}

// The Voronoi cells depend on the points only: Lloyd with flips and Lloyd with full rebuilds
// follow the same energies, up to the density, which is linear in each tet of the current mesh
// (TetGen's rebuild leaves a few faces near the boundary non-Delaunay, so the two meshes differ
// there): a few 1e-6 relative.
TEST(RelocateVertices3, LloydWithFlipsFollowsLloydWithRebuilds) {
  MeshData d = testing::cube_sphere(0.12, 0.1);
  TetMesh a = d.tet, b = d.tet;
  Lloyd3Options o;
  o.lloyd.max_iterations = 6;
  o.lloyd.tolerance = 0;
  o.local_flips = true;
  const LloydResult ra = lloyd_optimize_3d(a, o);
  o.local_flips = false;
  const LloydResult rb = lloyd_optimize_3d(b, o);
  ASSERT_EQ(ra.history.size(), rb.history.size());
  int flipped = 0;
  for (std::size_t i = 0; i < ra.history.size(); ++i) {
    EXPECT_NEAR(ra.history[i].energy, rb.history[i].energy, 2e-5 * rb.history[i].energy) << i;
    flipped += !ra.history[i].rebuilt;
  }
  EXPECT_GT(flipped, 0);
}

}  // namespace
}  // namespace cvtmesh
