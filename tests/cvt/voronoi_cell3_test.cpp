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
  const CellMesh cm = prepare_cell_mesh(m);
  std::vector<double> rho(m.nb_vertices());
  for (int v = 0; v < m.nb_vertices(); ++v)
    rho[v] = 1.0 + m.point(v)[0] + 2 * m.point(v)[2];  // linear density
  CellWorkspace ws;
  int compared = 0;
  for (int v = 0; v < m.nb_vertices(); ++v) {
    CellIntegrals dual;
    if (!dual_voronoi_cell(m, cm, v, &rho, dual)) continue;
    const CellIntegrals clip = restricted_voronoi_cell(m, cm, v, ws, &rho);
    ++compared;
    EXPECT_NEAR(dual.volume, clip.volume, 1e-9 * clip.volume) << v;
    EXPECT_NEAR(dual.mass, clip.mass, 1e-9 * clip.mass) << v;
    const Vec3 a = dual.centroid(m.point(v)), b = clip.centroid(m.point(v));
    EXPECT_NEAR(std::sqrt(norm2(a - b)), 0.0, 1e-9) << v;
  }
  EXPECT_GT(compared, m.nb_vertices() / 10);
}

}  // namespace
}  // namespace cvtmesh
