#include "core/cvt/voronoi_cell3.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/cvt/lloyd3.h"
#include "core/delaunay/delaunay3.h"
#include "core/io/read_mesh.h"
#include "core/pipeline/verify_mesh.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

TEST(VoronoiCell3, RestrictedCellsPartitionTheDomain) {
  MeshData d = testing::cube_sphere(0.15, 0.12);
  const TetMesh& m = d.tet;
  const CellMesh cm = prepare_cell_mesh(m);
  CellWorkspace ws;
  double total = 0;
  for (int v = 0; v < m.nb_vertices(); ++v) total += restricted_voronoi_cell(m, cm, v, ws).volume;
  const double vol = region_volumes(m)[0].second;
  EXPECT_NEAR(total, vol, 1e-3 * vol);
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

TEST(VoronoiCell3, DualDecompositionMatchesClippingForInteriorCells) {
  MeshData d = testing::cube_sphere(0.09, 0.07, /*gmsh_optimize=*/true);
  // Gmsh's optimizer leaves non-Delaunay faces: rebuild the constrained Delaunay mesh first.
  Delaunay3::create("tetgen")->retetrahedralize(d.tet);
  const TetMesh& m = d.tet;
  std::vector<double> rho(m.nb_vertices());
  for (int v = 0; v < m.nb_vertices(); ++v)
    rho[v] = 1.0 + m.point(v)[0] + 2 * m.point(v)[2];  // linear density
  const CellMesh cm = prepare_cell_mesh(m, &rho);
  CellWorkspace ws;
  int compared = 0;
  for (int v = 0; v < m.nb_vertices(); ++v) {
    CellIntegrals dual;
    if (!dual_voronoi_cell(m, cm, v, dual)) continue;
    const CellIntegrals clip = restricted_voronoi_cell(m, cm, v, ws, &rho);
    ++compared;
    EXPECT_NEAR(dual.volume, clip.volume, 1e-9 * clip.volume) << v;
    EXPECT_NEAR(dual.mass, clip.mass, 1e-9 * clip.mass) << v;
    const Vec3 a = dual.centroid(m.point(v)), b = clip.centroid(m.point(v));
    EXPECT_NEAR(std::sqrt(norm2(a - b)), 0.0, 1e-9) << v;
  }
  EXPECT_GT(compared, m.nb_vertices() / 10);
  // Under a constant density the pieces' energies (second moments about the vertex) are exact
  // too.
  const CellMesh cm1 = prepare_cell_mesh(m, nullptr);
  int compared1 = 0;
  for (int v = 0; v < m.nb_vertices(); ++v) {
    CellIntegrals dual;
    if (!dual_voronoi_cell(m, cm1, v, dual)) continue;
    const CellIntegrals clip = restricted_voronoi_cell(m, cm1, v, ws, nullptr);
    ++compared1;
    EXPECT_NEAR(dual.volume, clip.volume, 1e-9 * clip.volume) << v;
    EXPECT_NEAR(dual.mass, clip.mass, 1e-9 * clip.mass) << v;
    EXPECT_NEAR(dual.energy, clip.energy, 1e-9 * clip.energy) << v;
    EXPECT_GT(dual.energy, 0) << v;
  }
  EXPECT_GT(compared1, m.nb_vertices() / 10);
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

// Boundary vertices take the dual too: exact on the flat cube faces, edges and corners; within
// 1e-3 of the clipped volume on the polyhedral ball (a curved, non-convex part of the boundary).
TEST(VoronoiCell3, DualDecompositionOfBoundaryVertices) {
  MeshData d = testing::cube_sphere(0.09, 0.07, /*gmsh_optimize=*/true);
  Delaunay3::create("tetgen")->retetrahedralize(d.tet);
  const TetMesh& m = d.tet;
  const CellMesh cm = prepare_cell_mesh(m);
  CellWorkspace ws;
  int flat = 0, ball = 0;
  for (int v = 0; v < m.nb_vertices(); ++v) {
    if (m.vclass[v].dim == 3) continue;
    CellIntegrals dual;
    if (!dual_voronoi_cell(m, cm, v, dual)) continue;
    const CellIntegrals clip = restricted_voronoi_cell(m, cm, v, ws);
    const double* z = m.point(v);
    const bool on_cube = std::fabs(z[0] - 0.5) > 0.499 || std::fabs(z[1] - 0.5) > 0.499 ||
                         std::fabs(z[2] - 0.5) > 0.499;
    if (on_cube) {
      ++flat;
      EXPECT_NEAR(dual.volume, clip.volume, 1e-9 * clip.volume) << v;
      EXPECT_NEAR(dual.energy, clip.energy, 1e-9 * clip.energy) << v;
      const Vec3 a = dual.centroid(z), b = clip.centroid(z);
      EXPECT_NEAR(std::sqrt(norm2(a - b)), 0.0, 1e-9) << v;
    } else {
      ++ball;
      EXPECT_NEAR(dual.volume, clip.volume, 1e-3 * clip.volume) << v;
    }
  }
  EXPECT_GT(flat, 500);
  EXPECT_GT(ball, 150);
}

}  // namespace
}  // namespace cvtmesh
