#include "core/smoothing/smooth_laplacian.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "core/mesh/check_mesh.h"
#include "core/mesh/vertex_tets.h"
#include "core/quality/quality_stats.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

using testing::make_tet_mesh;
using testing::total_volume;
using testing::unoptimized_cube_sphere;

// An octahedron-like star: the free vertex 0 at (x0,y0,z0) and 8 tets to the faces of the
// polyhedron with apexes 1 = (ax,0,0), 2 = (-1,0,0) and the square (0,+-1,0), (0,0,+-1).
// With ax < 0 the polyhedron is dented: the mean of the neighbours, (ax-1)/6 on the x axis, lies
// outside it.
TetMesh star(double ax, double x0, double y0 = 0, double z0 = 0) {
  std::vector<std::array<int, 4>> tets;
  for (int a : {1, 2})
    for (int y : {3, 4})
      for (int z : {5, 6}) tets.push_back({0, a, y, z});
  return make_tet_mesh(
      {{x0, y0, z0}, {ax, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}, tets,
      /*interior=*/{0});
}

double min_q(const TetMesh& m) {
  const auto q = element_qualities(m, Measure::kQ);
  return *std::min_element(q.begin(), q.end());
}

TEST(SmoothLaplacian, MovesAFreeVertexToTheMeanOfItsNeighbours) {
  TetMesh m = star(1, 0.3, 0.2, -0.1);
  ASSERT_TRUE(check_mesh(m).ok);
  const double before = min_q(m);
  const SmoothStats s = smooth_laplacian(m);
  EXPECT_EQ(s.nb_moved, 1);
  EXPECT_EQ(m.point(0)[0], 0.0);
  EXPECT_EQ(m.point(0)[1], 0.0);
  EXPECT_EQ(m.point(0)[2], 0.0);
  EXPECT_GE(min_q(m), before);
  EXPECT_TRUE(check_mesh(m).ok);
}

TEST(SmoothLaplacian, RejectsAMoveThatWouldInvertATet) {
  // Dented at x = -0.5: the full step to x = -0.25 leaves the polyhedron, the half step lands on
  // the dent's apex (flat tets). The vertex must stay.
  TetMesh m = star(-0.5, -0.75);
  ASSERT_TRUE(check_mesh(m).ok);
  const SmoothStats s = smooth_laplacian(m);
  EXPECT_EQ(s.nb_rejected, 1);
  EXPECT_EQ(s.nb_moved + s.nb_half, 0);
  EXPECT_EQ(m.point(0)[0], -0.75);
  EXPECT_EQ(check_mesh(m).nb_inverted, 0);
}

TEST(SmoothLaplacian, TakesHalfAStepWhenTheFullStepIsRejected) {
  TetMesh m = star(-0.5, -0.95);
  ASSERT_TRUE(check_mesh(m).ok);
  const double before = min_q(m);
  const SmoothStats s = smooth_laplacian(m);
  EXPECT_EQ(s.nb_half, 1);
  EXPECT_DOUBLE_EQ(m.point(0)[0], -0.95 + 0.5 * (-0.25 + 0.95));
  EXPECT_GE(min_q(m), before);
  EXPECT_TRUE(check_mesh(m).ok);
  // Without half steps the vertex stays.
  TetMesh n = star(-0.5, -0.95);
  SmoothOptions o;
  o.half_step = false;
  EXPECT_EQ(smooth_laplacian(n, o).nb_rejected, 1);
  EXPECT_EQ(n.point(0)[0], -0.95);
}

TEST(SmoothLaplacian, NeverInvertsNeverLowersTheMinimumAndNeverMovesTheBoundary) {
  TetMesh m = unoptimized_cube_sphere();
  ASSERT_TRUE(check_mesh(m).ok);
  const TetMesh before = m;
  const double vol = total_volume(m);
  SmoothOptions o;
  o.passes = 3;
  const SmoothStats s = smooth_laplacian(m, o);
  EXPECT_GT(s.nb_moved, 0);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_EQ(c.nb_inverted, 0);
  EXPECT_GE(min_q(m), min_q(before));
  EXPECT_EQ(s.min_after, min_q(m));
  EXPECT_EQ(m.tets, before.tets);  // connectivity untouched
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim < 3)
      for (int k = 0; k < 3; ++k) ASSERT_EQ(m.point(v)[k], before.point(v)[k]) << "vertex " << v;
  EXPECT_NEAR(total_volume(m), vol, 1e-12 * vol);  // the boundary is fixed
}

TEST(SmoothLaplacian, NeverLowersTheLocalMinimumOfAStar) {
  // Free only an independent set of interior vertices (no two in a common tet): their stars are
  // disjoint and their neighbours fixed, so the minimum over each star can be checked per vertex.
  TetMesh m = unoptimized_cube_sphere();
  const VertexTets vt = vertex_tets(m);
  std::vector<char> blocked(m.nb_vertices(), 0);
  std::vector<int> free;
  for (int v = 0; v < m.nb_vertices(); ++v) {
    if (m.vclass[v].dim < 3 || blocked[v]) continue;
    free.push_back(v);
    for (const int* t = vt.begin_of(v); t != vt.end_of(v); ++t)
      for (int k = 0; k < 4; ++k) blocked[m.tets[4 * *t + k]] = 1;
  }
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim == 3 && std::find(free.begin(), free.end(), v) == free.end())
      m.vclass[v].dim = 2;
  ASSERT_GT(free.size(), 100u);
  auto star_min = [&](const TetMesh& mesh, int v) {
    double q = std::numeric_limits<double>::infinity();
    for (const int* t = vt.begin_of(v); t != vt.end_of(v); ++t) {
      const int* tv = &mesh.tets[4 * *t];
      q = std::min(q, tet_quality(mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]),
                                  mesh.point(tv[3]), Measure::kQ));
    }
    return q;
  };
  std::vector<double> before;
  for (int v : free) before.push_back(star_min(m, v));
  const TetMesh start = m;
  const SmoothStats s = smooth_laplacian(m);
  EXPECT_GT(s.nb_moved + s.nb_half, 0);
  EXPECT_GT(s.nb_rejected, 0);  // Laplacian alone would lower some local minimum
  int moved = 0;
  for (std::size_t i = 0; i < free.size(); ++i) {
    EXPECT_GE(star_min(m, free[i]), before[i]) << "vertex " << free[i];
    if (m.point(free[i])[0] != start.point(free[i])[0]) ++moved;
  }
  EXPECT_EQ(moved, s.nb_moved + s.nb_half);
  EXPECT_TRUE(check_mesh(m).ok);
}

}  // namespace
}  // namespace cvtmesh
