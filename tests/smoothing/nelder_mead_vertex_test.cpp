// The simplex-search placement of one vertex within bounds (nelder_mead_vertex.h): the centre
// of an octahedron of 8 tets, pulled towards a corner.
#include "core/smoothing/nelder_mead_vertex.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "core/mesh/check_mesh.h"
#include "core/quality/element_time_step.h"
#include "core/quality/quality.h"
#include "tests/support/test_meshes.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

// The octahedron |x| + |y| + |z| <= 1 as 8 tets around its centre (vertex 6), which sits at c.
TetMesh octahedron(const std::array<double, 3>& c) {
  std::vector<std::array<double, 3>> pts = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0},
                                            {0, 0, 1}, {0, 0, -1}, c};
  std::vector<std::array<int, 4>> tets;
  for (int x : {0, 1})
    for (int y : {2, 3})
      for (int z : {4, 5}) {
        // Positively oriented: the centre, then the face in the orientation that makes it so.
        const bool odd = (x == 1) != (y == 3) != (z == 5);
        tets.push_back(odd ? std::array<int, 4>{6, x, z, y} : std::array<int, 4>{6, x, y, z});
      }
  TetMesh m = testing::make_tet_mesh(pts, tets);
  return m;
}

struct StarRange {
  double q_min = 1e300, angle_min = 1e300, angle_max = 0, dt_min = 1e300;
};

StarRange star_range(const TetMesh& m) {
  StarRange r;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * static_cast<std::size_t>(t)];
    const std::array<double, 4> q =
        tet_table_qualities(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
    r.q_min = std::min(r.q_min, q[0]);
    r.angle_min = std::min(r.angle_min, q[2]);
    r.angle_max = std::max(r.angle_max, q[3]);
    r.dt_min = std::min(r.dt_min,
                        tet_time_step(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])));
  }
  return r;
}

std::vector<int> all_tets(const TetMesh& m) {
  std::vector<int> s(static_cast<std::size_t>(m.nb_tets()));
  for (int t = 0; t < m.nb_tets(); ++t) s[t] = t;
  return s;
}

TEST(NelderMeadVertex, WalksFromOutsideTheBoundsIntoThemAndRaisesTheMinimum) {
  TetMesh m = octahedron({0.6, 0.1, 0.05});
  ASSERT_TRUE(check_mesh(m).ok);
  ASSERT_EQ(testing::nb_not_positive(m), 0);
  const StarRange before = star_range(m);
  NelderMeadVertexOptions o;
  o.angle_floor = 40;
  o.angle_ceiling = 120;
  o.dt_floor = 0.5 * before.dt_min;
  ASSERT_LT(before.angle_min, o.angle_floor);  // the start is outside the bounds
  const std::vector<int> star = all_tets(m);
  const NelderMeadVertexResult r = nelder_mead_vertex(m, 6, star.data(), 8, o);
  EXPECT_TRUE(r.moved);
  EXPECT_LT(r.before, 0);  // outside the bounds
  EXPECT_GT(r.after, 0);
  const StarRange after = star_range(m);
  EXPECT_GE(after.angle_min, o.angle_floor);
  EXPECT_LE(after.angle_max, o.angle_ceiling);
  EXPECT_GE(after.dt_min, o.dt_floor);
  EXPECT_GT(after.q_min, before.q_min);
  EXPECT_EQ(testing::nb_not_positive(m), 0);
  // The fixed vertices never move.
  const TetMesh start = octahedron({0.6, 0.1, 0.05});
  for (int v = 0; v < 6; ++v)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(m.point(v)[k], start.point(v)[k]);
}

TEST(NelderMeadVertex, LeavesTheVertexWhereItWasWhenTheBoundsCannotBeMet) {
  // No position of the centre gives every tet a dihedral angle of at least 80 degrees (at the
  // true centre the smallest is 54.7).
  TetMesh m = octahedron({0.2, 0.1, 0.05});
  const TetMesh start = m;
  NelderMeadVertexOptions o;
  o.angle_floor = 80;
  const std::vector<int> star = all_tets(m);
  const NelderMeadVertexResult r = nelder_mead_vertex(m, 6, star.data(), 8, o);
  EXPECT_FALSE(r.moved);
  EXPECT_EQ(m.xyz, start.xyz);
}

TEST(NelderMeadVertex, WithinLooseBoundsItFindsTheCentre) {
  TetMesh m = octahedron({0.3, -0.2, 0.1});
  NelderMeadVertexOptions o;
  o.max_evaluations = 600;
  const std::vector<int> star = all_tets(m);
  const NelderMeadVertexResult r = nelder_mead_vertex(m, 6, star.data(), 8, o);
  EXPECT_TRUE(r.moved);
  EXPECT_GT(r.after, r.before);
  // The regular star's minimum: every tet (centre + a face) is the same.
  const TetMesh centred = octahedron({0, 0, 0});
  EXPECT_NEAR(star_range(m).q_min, star_range(centred).q_min, 1e-3);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(m.point(6)[k], 0, 1e-2);
}

}  // namespace
}  // namespace cvtmesh
