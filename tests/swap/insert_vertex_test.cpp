// Interior vertex insertion: the cavity is replaced by the tets joining the new point to its
// boundary faces, only when it is star-shaped from the point and holds no vertex inside.
#include "core/swap/insert_vertex.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/mesh/check_mesh.h"
#include "core/swap/constrained_faces.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

using testing::boundary_faces;
using testing::constrained_triples;
using testing::nb_not_positive;
using testing::total_volume;

std::vector<int> all_tets(const TetMesh& m) {
  std::vector<int> ids;
  for (int t = 0; t < m.nb_tets(); ++t) ids.push_back(t);
  return ids;
}

TEST(InsertVertex, TheCubeCentreSplitsTheSixKuhnTetsIntoTwelve) {
  TetMesh m = testing::cube6();
  m.node_tags.assign(8, 0);
  for (int v = 0; v < 8; ++v) m.node_tags[v] = 10 + v;
  const TetMesh start = m;
  const double p[3] = {0.5, 0.5, 0.5};  // on the diagonal every tet shares: no tet holds it inside
  SwapPlan plan = plan_insert_vertex(m, all_tets(m), p);
  ASSERT_EQ(plan.status, SwapStatus::kOk);
  EXPECT_EQ(plan.new_tets.size(), 12u);  // the 12 boundary triangles of the cube
  const int v = insert_vertex(m, plan, p);
  EXPECT_EQ(v, 8);
  EXPECT_EQ(m.nb_vertices(), 9);
  EXPECT_EQ(m.vclass[v].dim, 3);
  EXPECT_EQ(m.vclass[v].entity, 1);  // the region
  ASSERT_EQ(m.node_tags.size(), 9u);
  EXPECT_EQ(m.node_tags[v], 0u);  // a vertex created by us
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_EQ(nb_not_positive(m), 0);
  EXPECT_EQ(boundary_faces(m), boundary_faces(start));
  EXPECT_EQ(constrained_triples(m), constrained_triples(start));
  EXPECT_NEAR(total_volume(m), 1.0, 1e-15);
  int around = 0;
  for (int t = 0; t < m.nb_tets(); ++t)
    for (int k = 0; k < 4; ++k) around += m.tets[4 * t + k] == v;
  EXPECT_EQ(around, 12);
}

TEST(InsertVertex, RefusesAPointOutsideTheKernelAndACavityWithAVertexInside) {
  TetMesh m = testing::cube6();
  const double outside[3] = {1.5, 0.5, 0.5};
  EXPECT_EQ(plan_insert_vertex(m, all_tets(m), outside).status, SwapStatus::kNotConvex);
  // A point on a boundary face's plane makes a flat tet: refused by the exact predicate.
  const double on_face[3] = {0.5, 0.5, 0.0};
  EXPECT_EQ(plan_insert_vertex(m, all_tets(m), on_face).status, SwapStatus::kNotConvex);
  // The star of an interior vertex: the vertex would be lost.
  // A bipyramid split from its centre (vertex 5).
  const TetMesh r = testing::make_tet_mesh(
      {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {-1, 1, 0}, {-1, -1, 0}, {0, 0, 0}},
      {{5, 1, 2, 3}, {5, 1, 3, 4}, {5, 1, 4, 2}, {5, 0, 3, 2}, {5, 0, 4, 3}, {5, 0, 2, 4}}, {5});
  ASSERT_TRUE(check_mesh(r).ok);
  const double q[3] = {0.1, 0, 0};
  EXPECT_EQ(plan_insert_vertex(r, all_tets(r), q).status, SwapStatus::kInteriorVertex);
  const TetMesh before = m;
  SwapPlan bad = plan_insert_vertex(m, all_tets(m), outside);
  EXPECT_THROW(insert_vertex(m, bad, outside), std::invalid_argument);
  EXPECT_EQ(m.tets, before.tets);
  EXPECT_EQ(m.xyz, before.xyz);
}

TEST(InsertVertex, CavitiesNeverCrossConstrainedFacesAndTheKernelCentreIsInside) {
  TetMesh m = testing::cube6();
  // An inner face of tet 0 made constrained (as an interface would be).
  int f0 = 0;
  while (m.adj[f0] < 0) ++f0;
  const int across = m.adj[f0] / 4;
  for (int k = 0; k < 3; ++k) m.tris.push_back(m.tets[kTetFace[f0][k]]);
  m.tri_surface.push_back(2);
  const ConstrainedFaces constrained = constrained_faces(m);
  // tet_cavity: a tet and its neighbours, none across a constrained face.
  for (int t = 0; t < m.nb_tets(); ++t) {
    const std::vector<int> c = tet_cavity(m, constrained, t);
    EXPECT_EQ(c.front(), t);
    int nb_neighbours = 0;
    for (int f = 0; f < 4; ++f) {
      const int b = m.adj[4 * t + f];
      if (b < 0) continue;
      const bool crosses = (t == 0 && b / 4 == across) || (t == across && b / 4 == 0);
      EXPECT_EQ(std::count(c.begin(), c.end(), b / 4), crosses ? 0 : 1) << t << " " << f;
      nb_neighbours += !crosses;
    }
    EXPECT_EQ(static_cast<int>(c.size()), 1 + nb_neighbours);
  }
  // Growth from the cube's centre (inside every circumsphere: the cube's) takes every tet but
  // `across`: it is reached around the diagonal, but taking it would put the constrained face
  // inside the cavity, and the insertion would delete it (an embedded surface's triangle in t15
  // was lost so); at most max_size tets.
  std::vector<int> c = {0};
  const double centre[3] = {0.5, 0.5, 0.5};
  grow_cavity(m, constrained, centre, c, 100);
  EXPECT_EQ(c.size(), 5u);
  EXPECT_EQ(std::count(c.begin(), c.end(), across), 0);
  // No two tets of the cavity share a constrained face.
  for (int t : c)
    for (int f = 0; f < 4; ++f) {
      const int b = m.adj[4 * t + f];
      if (b < 0 || std::count(c.begin(), c.end(), b / 4) == 0) continue;
      const int* tv = &m.tets[4 * t];
      EXPECT_EQ(
          constrained.count(face_key(tv[kTetFace[f][0]], tv[kTetFace[f][1]], tv[kTetFace[f][2]])),
          0u)
          << t << " " << f;
    }
  std::vector<int> capped = {0};
  grow_cavity(m, constrained, centre, capped, 4);
  EXPECT_EQ(capped.size(), 4u);
  TetMesh two = m;  // the same with every inner face constrained: nothing to grow into
  for (int t = 0; t < two.nb_tets(); ++t)
    for (int f = 0; f < 4; ++f)
      if (two.adj[4 * t + f] >= 0) {
        for (int k = 0; k < 3; ++k) two.tris.push_back(two.tets[4 * t + kTetFace[f][k]]);
        two.tri_surface.push_back(2);
      }
  std::vector<int> alone = {0};
  grow_cavity(two, constrained_faces(two), centre, alone, 100);
  EXPECT_EQ(alone.size(), 1u);
  // The kernel centre of the cube: the point farthest from its 6 face planes, the centre.
  m = testing::cube6();
  double p[3];
  const double d = cavity_kernel_center(m, all_tets(m), p);
  EXPECT_NEAR(d, 0.5, 1e-12);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], 0.5, 1e-12);
  // From a tet of the cube alone: a point strictly inside it, from which it is star-shaped.
  const double d0 = cavity_kernel_center(m, {0}, p);
  EXPECT_GT(d0, 0);
  EXPECT_EQ(plan_insert_vertex(m, {0}, p).status, SwapStatus::kOk);
}

}  // namespace
}  // namespace cvtmesh
