// The 3D flips on degenerate geometry: cospherical points (cube lattices, where every
// triangulation of a cube is Delaunay and many swaps tie), nearly flat slivers (coordinates
// perturbed by 1e-14) and points exactly on the boundary (coplanar hull faces, points on hull
// edges). The swaps must terminate on their own, never create an inverted or flat tet (exact
// orient3d), never touch the boundary and keep the volume.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/mesh/check_mesh.h"
#include "core/quality/quality_stats.h"
#include "core/swap/flip23.h"
#include "core/swap/flip32.h"
#include "core/swap/remove_edge.h"
#include "core/swap/swap_slivers.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

using testing::boundary_faces;
using testing::constrained_triples;
using testing::cube_lattice;
using testing::face_opposite;
using testing::local_edge;
using testing::nb_not_positive;
using testing::ring_mesh;
using testing::tet_vertex_sets;
using testing::total_volume;

// n^3 unit cubes, each split into the 6 Kuhn tets around its diagonal (a conforming mesh: every
// tet is congruent, all 8 corners of each cube cospherical).
TetMesh kuhn_grid(int n) {
  std::vector<std::array<double, 3>> pts;
  std::vector<int> interior;
  auto id = [n](int i, int j, int k) { return (i * (n + 1) + j) * (n + 1) + k; };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        pts.push_back({double(i), double(j), double(k)});
        if (i > 0 && i < n && j > 0 && j < n && k > 0 && k < n) interior.push_back(id(i, j, k));
      }
  std::vector<std::array<int, 4>> tets;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        auto c = [&](int b) { return id(i + (b & 1), j + ((b >> 1) & 1), k + ((b >> 2) & 1)); };
        for (const auto& t : {std::array<int, 4>{0, 1, 3, 7},
                              {0, 1, 5, 7},
                              {0, 2, 3, 7},
                              {0, 2, 6, 7},
                              {0, 4, 5, 7},
                              {0, 4, 6, 7}})
          tets.push_back({c(t[0]), c(t[1]), c(t[2]), c(t[3])});
      }
  return testing::make_tet_mesh(pts, tets, interior);
}

// swap_slivers with room for 100 passes: it must stop by itself (nothing accepted in a pass),
// and leave a valid, positively oriented mesh with the same boundary, vertices and volume, and a
// minimum quality no lower than before. A second run then accepts nothing.
void expect_swaps_terminate_and_keep_invariants(TetMesh m, const std::string& what) {
  SCOPED_TRACE(what);
  const MeshCheck c0 = check_mesh(m);
  ASSERT_TRUE(c0.ok) << c0.problems.front();
  ASSERT_EQ(nb_not_positive(m), 0);
  const TetMesh start = m;
  for (Measure measure : {Measure::kQ, Measure::kMinAngle}) {
    m = start;
    SwapOptions o;
    o.measure = measure;
    o.max_passes = 100;
    const double min_before = testing::global_min_quality(m, measure);
    const SwapStats s = swap_slivers(m, o);
    EXPECT_LT(s.passes, o.max_passes) << "did not converge";
    const MeshCheck c = check_mesh(m);
    EXPECT_TRUE(c.ok) << c.problems.front();
    EXPECT_EQ(nb_not_positive(m), 0);
    EXPECT_GE(testing::global_min_quality(m, measure), min_before);
    EXPECT_EQ(boundary_faces(m), boundary_faces(start));
    EXPECT_EQ(constrained_triples(m), constrained_triples(start));
    EXPECT_EQ(m.xyz, start.xyz);
    EXPECT_NEAR(total_volume(m), total_volume(start), 1e-12 * total_volume(start));
    const SwapStats again = swap_slivers(m, o);
    EXPECT_EQ(again.nb_flip23 + again.nb_flip32 + again.nb_edge_removals, 0);
    EXPECT_EQ(again.passes, 1);
  }
}

TEST(SwapDegenerate, KuhnGridOfCosphericalCubes) {
  // Every tet congruent: no swap raises the minimum of its tets, nothing may change.
  TetMesh m = kuhn_grid(4);
  const auto before = tet_vertex_sets(m);
  expect_swaps_terminate_and_keep_invariants(m, "kuhn grid 4^3");
  swap_slivers(m);
  EXPECT_EQ(tet_vertex_sets(m), before);
}

TEST(SwapDegenerate, DelaunayOfTheCubeLattice) {
  // The 5x5x5 lattice: 8 cospherical points per cube, 25 coplanar per hull face. TetGen breaks the
  // ties (no flat tet, exact predicates) with diagonals of its own choice; whatever it gives, the
  // swaps settle.
  expect_swaps_terminate_and_keep_invariants(testing::delaunay_of_points(cube_lattice(4)),
                                             "lattice 5^3");
}

TEST(SwapDegenerate, LatticeWithInteriorPointsMovedBy1e14) {
  // Nearly cospherical: the Delaunay tets of the perturbed lattice include slivers whose volume
  // is of the order of the perturbation.
  const TetMesh m = testing::delaunay_of_points(cube_lattice(4, 1e-14));
  ASSERT_EQ(m.nb_vertices(), 125);
  double vmin = 1;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    vmin = std::min(vmin, tet_volume(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])));
  }
  EXPECT_LT(vmin, 1e-12) << "no near-flat sliver: the test does not test what it says";
  expect_swaps_terminate_and_keep_invariants(m, "lattice 5^3 jittered 1e-14");
}

TEST(SwapDegenerate, PointsExactlyOnHullFacesAndEdges) {
  // The lattice plus the midpoints of the hull edges of the bottom face's squares and the centres
  // of the squares of the top face: points exactly on boundary edges and faces.
  const std::vector<double> p = testing::cube_lattice_with_hull_points();
  expect_swaps_terminate_and_keep_invariants(testing::delaunay_of_points(p), "points on the hull");
}

TEST(SwapDegenerate, OneSliverOfFourNearlyCoplanarPointsIsRemoved) {
  // A square whose corners are 1e-14 above/below z = 0, between two apexes: TetGen keeps the
  // square as a sliver tet (volume ~1e-14) with two tets above and two below it.
  const double e = 1e-14;
  const TetMesh m = testing::delaunay_of_points(
      {0, 0, e, 1, 0, -e, 1, 1, e, 0, 1, -e, 0.5, 0.5, 1, 0.5, 0.5, -1});
  double vmin = 1;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    vmin = std::min(vmin, tet_volume(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])));
  }
  ASSERT_LT(vmin, 1e-12) << "TetGen gave no sliver here";
  expect_swaps_terminate_and_keep_invariants(m, "one sliver");
  TetMesh s = m;
  swap_slivers(s);
  double vmin_after = 1;
  for (int t = 0; t < s.nb_tets(); ++t) {
    const int* v = &s.tets[4 * t];
    vmin_after = std::min(vmin_after,
                          tet_volume(s.point(v[0]), s.point(v[1]), s.point(v[2]), s.point(v[3])));
  }
  EXPECT_GT(vmin_after, 0.1);  // the four tets around the axis (or around a diagonal)
}

// Exactly degenerate local configurations: the flip would create a flat tet; it is refused and
// the mesh is unchanged.

TEST(FlipDegenerate, Flip23RefusesWhenTheNewEdgeMeetsAnEdgeOrAVertexOfTheFace) {
  const double s = std::sqrt(3.0) / 2;
  // Face a=(1,0,0), b=(-1/2,s,0), c=(-1/2,-s,0); d=(0,0,-1). e=(-1,0,1): the segment d-e meets
  // z = 0 at (-1/2,0,0), on the edge b-c; e=(2,0,1): at (1,0,0) = a.
  for (double xe : {-1.0, 2.0}) {
    TetMesh m =
        testing::make_tet_mesh({{1, 0, 0}, {-0.5, s, 0}, {-0.5, -s, 0}, {0, 0, -1}, {xe, 0, 1}},
                               {{0, 1, 2, 3}, {0, 1, 2, 4}});
    ASSERT_TRUE(check_mesh(m).ok);
    const auto before = tet_vertex_sets(m);
    EXPECT_EQ(flip23(m, 0, face_opposite(m, 0, 3)).status, SwapStatus::kNotConvex) << xe;
    EXPECT_EQ(tet_vertex_sets(m), before);
  }
}

TEST(FlipDegenerate, EdgeRemovalRefusesARingCoplanarWithAnEndOfTheEdge) {
  // The ring lies in the plane z = 1 of q = (0,0,1): every new tet on the q side would be flat.
  // n = 3 is the 3-2 flip.
  {
    TetMesh m = ring_mesh(3, 1.0, 1.0);
    ASSERT_TRUE(check_mesh(m).ok);
    ASSERT_EQ(nb_not_positive(m), 0);
    EXPECT_EQ(flip32(m, 0, local_edge(m, 0, 0, 1)).status, SwapStatus::kNotConvex);
    EXPECT_EQ(m.nb_tets(), 3);
  }
  for (int n = 4; n <= 7; ++n) {
    TetMesh m = ring_mesh(n, 1.0, 1.0);
    ASSERT_TRUE(check_mesh(m).ok);
    const auto before = tet_vertex_sets(m);
    EXPECT_EQ(remove_edge(m, 0, local_edge(m, 0, 0, 1)).status, SwapStatus::kNotConvex) << n;
    EXPECT_EQ(tet_vertex_sets(m), before);
  }
}

}  // namespace
}  // namespace cvtmesh
