#include "core/swap/remove_edge.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/mesh/check_mesh.h"
#include "core/swap/edge_ring.h"
#include "core/swap/polygon_triangulations.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

using testing::boundary_faces;
using testing::local_edge;
using testing::ring_mesh;
using testing::tet_vertex_sets;
using testing::total_volume;

TEST(PolygonTriangulations, CountsAreCatalanNumbersAndEachTilesThePolygon) {
  const int catalan[8] = {0, 0, 0, 1, 2, 5, 14, 42};
  for (int n = 3; n <= 7; ++n) {
    const PolygonTriangulations& t = polygon_triangulations(n);
    EXPECT_EQ(static_cast<int>(t.triangulations.size()), catalan[n]) << "n = " << n;
    EXPECT_EQ(static_cast<int>(t.triangles.size()), n * (n - 1) * (n - 2) / 6);
    // On a regular n-gon every triangulation's triangles are counter-clockwise and their areas
    // add up to the polygon's; no two triangulations are the same.
    std::vector<std::array<double, 2>> p(n);
    for (int i = 0; i < n; ++i) p[i] = {std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n)};
    const double area = 0.5 * n * std::sin(2 * M_PI / n);
    std::set<std::set<int>> distinct;
    for (const auto& tr : t.triangulations) {
      ASSERT_EQ(static_cast<int>(tr.size()), n - 2);
      double sum = 0;
      for (int i : tr) {
        const auto& abc = t.triangles[i];
        const double a2 = (p[abc[1]][0] - p[abc[0]][0]) * (p[abc[2]][1] - p[abc[0]][1]) -
                          (p[abc[1]][1] - p[abc[0]][1]) * (p[abc[2]][0] - p[abc[0]][0]);
        EXPECT_GT(a2, 0);
        sum += 0.5 * a2;
      }
      EXPECT_NEAR(sum, area, 1e-12);
      distinct.insert(std::set<int>(tr.begin(), tr.end()));
    }
    EXPECT_EQ(distinct.size(), t.triangulations.size());
  }
  EXPECT_THROW(polygon_triangulations(8), std::invalid_argument);
  EXPECT_THROW(polygon_triangulations(2), std::invalid_argument);
}

TEST(EdgeRing, WalksCounterClockwiseAroundTheEdge) {
  const TetMesh m = ring_mesh(5);
  const EdgeRing r = edge_ring(m, 2, local_edge(m, 2, 0, 1), 7);
  ASSERT_TRUE(r.closed);
  ASSERT_EQ(r.ring.size(), 5u);
  for (int i = 0; i < 5; ++i)
    EXPECT_GT(
        orient3d(m.point(r.p), m.point(r.q), m.point(r.ring[i]), m.point(r.ring[(i + 1) % 5])), 0);
  EXPECT_FALSE(edge_ring(m, 2, local_edge(m, 2, 0, 1), 4).closed);  // larger than 4
  const EdgeRing b = edge_ring(m, 0, local_edge(m, 0, 0, 2), 7);
  EXPECT_TRUE(b.on_boundary);
}

// The ring of n tets around a vertical edge through a regular n-gon.
class RemoveEdgeRing : public ::testing::TestWithParam<int> {};

TEST_P(RemoveEdgeRing, GivesTwoNMinusFourTetsWithTheSameBoundaryAndVolume) {
  const int n = GetParam();
  TetMesh m = ring_mesh(n);
  ASSERT_TRUE(check_mesh(m).ok);
  const auto outer = boundary_faces(m);
  const double vol = total_volume(m);
  const SwapPlan plan = remove_edge(m, 0, local_edge(m, 0, 0, 1));
  ASSERT_EQ(plan.status, SwapStatus::kOk);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  const auto after = tet_vertex_sets(m);
  EXPECT_EQ(static_cast<int>(after.size()), 2 * n - 4);
  EXPECT_EQ(boundary_faces(m), outer);  // none of the outer faces changed
  EXPECT_NEAR(total_volume(m), vol, 1e-12 * vol);
  for (const auto& t : after) {  // the edge (0,1) is gone
    const bool has_p = std::find(t.begin(), t.end(), 0) != t.end();
    const bool has_q = std::find(t.begin(), t.end(), 1) != t.end();
    EXPECT_FALSE(has_p && has_q);
  }
}

TEST_P(RemoveEdgeRing, PicksTheMaxMinTriangulation) {
  const int n = GetParam();
  // Perturb the ring so that the triangulations differ in quality.
  TetMesh m = ring_mesh(n);
  for (int i = 0; i < n; ++i) {
    m.point(2 + i)[0] *= 1.0 + 0.13 * i;
    m.point(2 + i)[2] = 0.07 * (i % 3);
  }
  ASSERT_TRUE(check_mesh(m).ok);
  const ConstrainedFaces cf = constrained_faces(m);
  for (Measure measure : {Measure::kQ, Measure::kMinAngle}) {
    const SwapPlan plan = plan_remove_edge(m, cf, 0, local_edge(m, 0, 0, 1), measure);
    ASSERT_EQ(plan.status, SwapStatus::kOk);
    // Brute force over the table.
    const EdgeRing r = edge_ring(m, 0, local_edge(m, 0, 0, 1), 7);
    const PolygonTriangulations& table = polygon_triangulations(n);
    double best = -std::numeric_limits<double>::infinity();
    for (const auto& tr : table.triangulations) {
      double worst = std::numeric_limits<double>::infinity();
      for (int i : tr) {
        const auto& abc = table.triangles[i];
        const double* A = m.point(r.ring[abc[0]]);
        const double* B = m.point(r.ring[abc[1]]);
        const double* C = m.point(r.ring[abc[2]]);
        const double* P = m.point(r.p);
        const double* Q = m.point(r.q);
        if (orient3d(A, B, C, Q) <= 0 || orient3d(A, C, B, P) <= 0)
          worst = -std::numeric_limits<double>::infinity();
        else
          worst =
              std::min({worst, tet_quality(A, B, C, Q, measure), tet_quality(A, C, B, P, measure)});
      }
      best = std::max(best, worst);
    }
    EXPECT_EQ(plan.new_min, best);
    EXPECT_EQ(plan.new_min, min_quality(m, plan.new_tets, measure));
    EXPECT_EQ(plan.old_min, min_quality(m, plan.old_tets, measure));
    EXPECT_EQ(static_cast<int>(plan.new_tets.size()), 2 * n - 4);
  }
}

// With a floor the planner gives the same plan as without one while the max-min triangulation
// is above the floor, and refuses (kRejected) once the floor reaches its minimum.
TEST_P(RemoveEdgeRing, AFloorChangesNothingBelowTheBestAndRefusesFromIt) {
  const int n = GetParam();
  TetMesh m = ring_mesh(n);
  for (int i = 0; i < n; ++i) {
    m.point(2 + i)[0] *= 1.0 + 0.11 * i;
    m.point(2 + i)[2] = 0.05 * (i % 3);
  }
  ASSERT_TRUE(check_mesh(m).ok);
  const ConstrainedFaces cf = constrained_faces(m);
  const EdgeRing r = edge_ring(m, 0, local_edge(m, 0, 0, 1), 7);
  ASSERT_TRUE(r.closed);
  for (Measure measure : {Measure::kQ, Measure::kMinAngle}) {
    const SwapPlan free = plan_remove_edge(m, cf, r, measure);
    ASSERT_EQ(free.status, SwapStatus::kOk);
    for (double f : {free.new_min - 1.0, 0.5 * free.new_min, std::nextafter(free.new_min, -1.0)}) {
      const SwapPlan floored = plan_remove_edge(m, cf, r, measure, f);
      ASSERT_EQ(floored.status, SwapStatus::kOk) << "floor " << f;
      EXPECT_EQ(floored.new_tets, free.new_tets);
      EXPECT_EQ(floored.new_min, free.new_min);
      EXPECT_EQ(floored.old_min, free.old_min);
    }
    for (double f : {free.new_min, free.new_min + 1e-3})
      EXPECT_EQ(plan_remove_edge(m, cf, r, measure, f).status, SwapStatus::kRejected)
          << "floor " << f;
  }
}

INSTANTIATE_TEST_SUITE_P(RingSizes, RemoveEdgeRing, ::testing::Values(3, 4, 5, 6, 7));

TEST(RemoveEdge, NeverRemovesAConstrainedFaceAndSkipsBoundaryEdges) {
  TetMesh m = ring_mesh(5);
  m.tris.insert(m.tris.end(), {0, 1, 4});  // an interior face around the edge, constrained
  m.tri_surface.push_back(2);
  ASSERT_TRUE(check_mesh(m).ok);
  const auto before = tet_vertex_sets(m);
  EXPECT_EQ(remove_edge(m, 0, local_edge(m, 0, 0, 1)).status, SwapStatus::kConstrainedFace);
  EXPECT_EQ(tet_vertex_sets(m), before);
  EXPECT_TRUE(check_mesh(m).ok);

  // An open ring: the edge is on the boundary.
  TetMesh open =
      testing::make_tet_mesh({{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}},
                             {{0, 1, 2, 3}, {0, 1, 3, 4}, {0, 1, 4, 5}});
  ASSERT_TRUE(check_mesh(open).ok);
  EXPECT_EQ(remove_edge(open, 1, local_edge(open, 1, 0, 1)).status, SwapStatus::kBoundary);
  EXPECT_EQ(open.nb_tets(), 3);
}

TEST(RemoveEdge, NeverMixesRegions) {
  TetMesh m = ring_mesh(4);
  m.tet_region[2] = 2;
  // The interfaces of tet 2 with its two neighbours are constrained triangles.
  for (int f = 0; f < 4; ++f)
    if (m.adj[4 * 2 + f] >= 0) {
      for (int k = 0; k < 3; ++k) m.tris.push_back(m.tets[4 * 2 + kTetFace[f][k]]);
      m.tri_surface.push_back(2);
    }
  ASSERT_TRUE(check_mesh(m).ok);
  const SwapPlan plan = remove_edge(m, 0, local_edge(m, 0, 0, 1));
  EXPECT_EQ(plan.status, SwapStatus::kMixedRegions);
  EXPECT_EQ(m.nb_tets(), 4);
  EXPECT_TRUE(check_mesh(m).ok);
}

TEST(RemoveEdge, RefusesARingWithNoValidTriangulation) {
  for (int n : {4, 6}) {
    TetMesh m = ring_mesh(n, 1.0, 2.0);  // ring above q
    ASSERT_TRUE(check_mesh(m).ok);
    EXPECT_EQ(remove_edge(m, 0, local_edge(m, 0, 0, 1)).status, SwapStatus::kNotConvex);
    EXPECT_EQ(m.nb_tets(), n);
  }
}

}  // namespace
}  // namespace cvtmesh
