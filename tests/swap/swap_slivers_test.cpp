#include "core/swap/swap_slivers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "core/mesh/check_mesh.h"
#include "core/pipeline/verify_mesh.h"
#include "core/quality/quality_stats.h"
#include "core/quality/time_step_guard.h"
#include "tests/support/thread_counts.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

using testing::boundary_faces;
using testing::constrained_triples;
using testing::total_volume;
using testing::unoptimized_cube_sphere;

std::string first_problem(const MeshCheck& c) {
  return c.problems.empty() ? "" : c.problems[0];
}

// The invariants of a swap pass on the unoptimized cube minus a ball, for one criterion.
void check_swap_invariants(Measure measure) {
  TetMesh m = unoptimized_cube_sphere();
  const TetMesh start = m;
  const MeshCheck c0 = check_mesh(m);
  ASSERT_TRUE(c0.ok) << first_problem(c0);
  const auto tris_before = constrained_triples(m);
  const auto outer_before = boundary_faces(m);
  const auto xyz_before = m.xyz;
  const double vol = total_volume(m);
  const double min_before = testing::global_min_quality(m, measure);

  SwapOptions o;
  o.measure = measure;
  const SwapStats s = swap_slivers(m, o);

  const MeshCheck c1 = check_mesh(m);
  EXPECT_TRUE(c1.ok) << first_problem(c1);
  EXPECT_EQ(c1.nb_inverted, 0);
  EXPECT_GT(testing::global_min_quality(m, Measure::kQ), 0.0);
  // Never lowers the minimum quality of the criterion's measure.
  EXPECT_GE(testing::global_min_quality(m, measure), min_before);
  EXPECT_EQ(s.min_before, min_before);
  EXPECT_EQ(s.min_after, testing::global_min_quality(m, measure));
  // Boundary triangles unchanged, both the constrained list and the faces of the tet complex.
  EXPECT_EQ(constrained_triples(m), tris_before);
  EXPECT_EQ(boundary_faces(m), outer_before);
  EXPECT_EQ(m.xyz, xyz_before);  // a swap never moves a vertex
  EXPECT_NEAR(total_volume(m), vol, 1e-12 * vol);
  EXPECT_NO_THROW(verify_optimized(start, m));  // the pipeline's own end-of-run invariants
  // The Delaunay Init has slivers whose interior edges can be removed: work was done, and the
  // counts add up to the change in the number of tets (2-3: +1, edge removal n: n-4).
  EXPECT_GT(s.nb_flip32 + s.nb_edge_removals, 0);
  long delta = s.nb_flip23;
  for (int n = 3; n <= 7; ++n) delta += s.nb_by_ring[n] * (n - 4);
  EXPECT_EQ(s.nb_tets_after - s.nb_tets_before, delta);
  EXPECT_EQ(s.nb_tets_after, m.nb_tets());  // compacted
  EXPECT_EQ(s.nb_flip32, s.nb_by_ring[3]);

  // Converged before max_passes: a second run finds nothing left to accept.
  if (s.passes < o.max_passes) {
    const SwapStats again = swap_slivers(m, o);
    EXPECT_EQ(again.nb_flip23 + again.nb_flip32 + again.nb_edge_removals, 0);
    EXPECT_EQ(again.passes, 1);
  }
}

TEST(SwapSlivers, QCriterionNeverLowersMinQualityAndKeepsBoundaryAndVolume) {
  check_swap_invariants(Measure::kQ);
}

TEST(SwapSlivers, DihedralCriterionNeverLowersMinDihedralAngle) {
  check_swap_invariants(Measure::kMinAngle);
}

TEST(SwapSlivers, TwoRegionsNeverMixAndTheInterfaceIsKept) {
  // Split the cube minus a ball into two regions by the plane x = 1/2 (tet centroids); the
  // jagged interface between them becomes constrained triangles, as Gmsh gives for two volumes.
  TetMesh m = unoptimized_cube_sphere();
  for (int t = 0; t < m.nb_tets(); ++t) {
    double x = 0;
    for (int k = 0; k < 4; ++k) x += m.point(m.tets[4 * t + k])[0] / 4;
    m.tet_region[t] = x < 0.5 ? 2 : 1;
  }
  for (int t = 0; t < m.nb_tets(); ++t)
    for (int f = 0; f < 4; ++f) {
      const int o = m.adj[4 * t + f];
      if (o >= 0 && o / 4 > t && m.tet_region[o / 4] != m.tet_region[t]) {
        for (int k = 0; k < 3; ++k) m.tris.push_back(m.tets[4 * t + kTetFace[f][k]]);
        m.tri_surface.push_back(99);
      }
    }
  const MeshCheck c0 = check_mesh(m);
  ASSERT_TRUE(c0.ok) << first_problem(c0);
  std::map<int, double> vol;
  for (int r : {1, 2}) vol[r] = total_volume(m, r);
  const auto tris_before = constrained_triples(m);
  const double min_before = testing::global_min_quality(m, Measure::kQ);
  const SwapStats s = swap_slivers(m);
  EXPECT_GT(s.nb_flip32 + s.nb_edge_removals, 0);
  const MeshCheck c = check_mesh(m);  // interfaces present, no unlisted face between regions
  EXPECT_TRUE(c.ok) << first_problem(c);
  EXPECT_EQ(constrained_triples(m), tris_before);
  EXPECT_GE(testing::global_min_quality(m, Measure::kQ), min_before);
  for (int r : {1, 2}) EXPECT_NEAR(total_volume(m, r), vol[r], 1e-12 * vol[r]) << "region " << r;
}

TEST(SwapSlivers, RejectsAMeasureWhereLargerIsNotBetter) {
  TetMesh m = testing::cube6();
  SwapOptions o;
  o.measure = Measure::kMaxAngle;
  EXPECT_THROW(swap_slivers(m, o), std::invalid_argument);
  o.measure = Measure::kQ;
  o.max_ring = 8;
  EXPECT_THROW(swap_slivers(m, o), std::invalid_argument);
}

TEST(SwapSlivers, LeavesTheKuhnCubeValid) {
  // Every edge of the 6-tet cube is on the boundary except the diagonal (ring of 6 whose
  // faces are all interior): whatever it does, the cube stays a valid mesh of the cube.
  TetMesh m = testing::cube6();
  const double min_before = testing::global_min_quality(m, Measure::kQ);
  swap_slivers(m);
  EXPECT_TRUE(check_mesh(m).ok);
  EXPECT_NEAR(total_volume(m), 1.0, 1e-12);
  EXPECT_GE(testing::global_min_quality(m, Measure::kQ), min_before);
}

// The tets are planned in parallel chunks and committed in order, a tet planned again where an
// earlier commit of its chunk changed its neighbourhood: the same mesh and the same counts for
// any number of threads, with the time-step guard too (its nodal sums read around the cavities).
TEST(SwapSlivers, SameResultForAnyNumberOfThreads) {
  for (const bool dt_guard : {false, true}) {
    const auto runs = testing::for_each_thread_count([dt_guard] {
      TetMesh m = unoptimized_cube_sphere();
      SwapOptions o;
      if (dt_guard) o.dt_guard = time_step_guard(m, 1.0);
      const SwapStats st = swap_slivers(m, o);
      return std::make_pair(std::move(m), st);
    });
    const SwapStats& first = runs[0].second;
    EXPECT_GT(first.nb_flip32 + first.nb_edge_removals + first.nb_flip23, 0);
    for (std::size_t k = 1; k < runs.size(); ++k) {
      SCOPED_TRACE("dt_guard " + std::to_string(dt_guard) + ", run " + std::to_string(k));
      const auto& [m, st] = runs[k];
      EXPECT_EQ(m.tets, runs[0].first.tets);
      EXPECT_EQ(m.tet_region, runs[0].first.tet_region);
      EXPECT_EQ(st.nb_tried, first.nb_tried);
      EXPECT_EQ(st.nb_flip23, first.nb_flip23);
      EXPECT_EQ(st.nb_by_ring, first.nb_by_ring);
      EXPECT_EQ(st.passes, first.passes);
    }
  }
}

}  // namespace
}  // namespace cvtmesh
