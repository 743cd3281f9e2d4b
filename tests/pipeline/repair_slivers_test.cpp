// The repair of boundary-locked slivers: a micro-case no flip or smoothing can fix, and the
// pipeline's polish on a small cube minus a ball.
#include "core/pipeline/repair_slivers.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh/check_mesh.h"
#include "core/pipeline/optimize.h"
#include "core/pipeline/verify_mesh.h"
#include "core/quality/quality_stats.h"
#include "core/quality/time_step_guard.h"
#include "core/smoothing/smooth_maxmin3.h"
#include "core/swap/swap_slivers.h"
#include "tests/support/test_meshes.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

using testing::boundary_faces;
using testing::constrained_triples;
using testing::global_min_quality;
using testing::nb_not_positive;

// A lens around the edge c-d (vertices 2, 3, at height eps above the x axis): below it the sliver
// (a, b, c, d) with a = 0 = (-1,0,0), b = 1 = (1,0,0), whose faces abc and abd are boundary
// triangles folded by 2 eps along ab; above it a fan of 7 tets (c, d, x_k, x_k+1) to the arc
// x_1..x_6 (vertices 4..9, unit circle of the plane y = 0). Every vertex is on the boundary
// (fixed); the sliver's edges are boundary edges or c-d, with 8 tets around it (more than an
// edge removal takes), and the 2-3 flips of its faces acd and bcd are not convex.
TetMesh locked_sliver(double eps) {
  std::vector<std::array<double, 3>> pts = {{-1, 0, 0}, {1, 0, 0}, {0, -1, eps}, {0, 1, eps}};
  for (double deg : {150.0, 125.0, 100.0, 80.0, 55.0, 30.0})
    pts.push_back({std::cos(deg * M_PI / 180), 0, std::sin(deg * M_PI / 180)});
  std::vector<std::array<int, 4>> tets = {{0, 1, 2, 3}, {2, 3, 0, 4}};
  for (int k = 4; k < 9; ++k) tets.push_back({2, 3, k, k + 1});
  tets.push_back({2, 3, 9, 1});
  return testing::make_tet_mesh(pts, tets);
}

TEST(RepairSlivers, InsertsAVertexIntoABoundaryLockedSliver) {
  TetMesh m = locked_sliver(0.02);
  ASSERT_TRUE(check_mesh(m).ok);
  const TetMesh start = m;
  const double q0 = global_min_quality(m, Measure::kQ);
  const double a0 = global_min_quality(m, Measure::kMinAngle);
  ASSERT_LT(a0, 3);  // a sliver
  // Locked: flips and smoothing leave it.
  TetMesh flipped = m;
  swap_slivers(flipped, SwapOptions{});
  smooth_maxmin3(flipped, MaxMinOptions{});
  EXPECT_EQ(global_min_quality(flipped, Measure::kQ), q0);

  const RepairStats s = repair_slivers(m, RepairOptions{});
  ::testing::Test::RecordProperty(
      "q_min", std::to_string(q0) + " -> " + std::to_string(global_min_quality(m, Measure::kQ)));
  EXPECT_EQ(s.nb_tried, 1);
  EXPECT_GE(s.nb_inserted, 1);
  EXPECT_EQ(m.nb_vertices(), start.nb_vertices() + s.nb_inserted);
  for (int v = start.nb_vertices(); v < m.nb_vertices(); ++v) {
    EXPECT_EQ(m.vclass[v].dim, 3);
    EXPECT_EQ(m.vclass[v].entity, 1);
  }
  // The local (here global) minimum rose well above the sliver's, in Q and in dihedral angle.
  EXPECT_GT(global_min_quality(m, Measure::kQ), 4 * q0);
  EXPECT_GT(global_min_quality(m, Measure::kMinAngle), 4 * a0);
  EXPECT_EQ(s.q_min_before, q0);
  EXPECT_EQ(s.q_min_after, global_min_quality(m, Measure::kQ));
  // Invariants: valid, no inverted tet, the boundary kept exactly, fixed vertices unmoved, volume.
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_EQ(nb_not_positive(m), 0);
  EXPECT_EQ(boundary_faces(m), boundary_faces(start));
  EXPECT_EQ(constrained_triples(m), constrained_triples(start));
  for (int v = 0; v < start.nb_vertices(); ++v)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(m.point(v)[k], start.point(v)[k]);
  const double vol = region_volumes(start)[0].second;
  EXPECT_NEAR(region_volumes(m)[0].second, vol, 1e-12 * vol);
  EXPECT_NO_THROW(verify_optimized(start, m));
}

TEST(RepairSlivers, WithoutInsertionTheLockedSliverStaysAndNothingChanges) {
  TetMesh m = locked_sliver(0.02);
  const TetMesh start = m;
  RepairOptions o;
  o.insert = false;
  const RepairStats s = repair_slivers(m, o);
  EXPECT_EQ(s.nb_inserted + s.nb_flip_smooth, 0);
  EXPECT_EQ(m.tets, start.tets);
  EXPECT_EQ(m.xyz, start.xyz);
  o.max_cavity = 0;
  EXPECT_THROW(repair_slivers(m, o), std::invalid_argument);
}

// The polished mesh of a small cube minus a ball (the pipeline without the repair), once.
const MeshData& polished_cube_sphere() {
  static const MeshData d = [] {
    MeshData m = testing::cube_sphere(0.14, 0.1);
    OptimizeOptions o;
    o.max_iterations = 10;
    o.polish_repair = false;
    o.auto_refine = false;  // the same path as the run with the repair below
    optimize(m, o);
    return m;
  }();
  return d;
}

TEST(RepairSlivers, NeverLowersTheMinimaOfAPolishedCubeSphereAndIsDeterministic) {
  const TetMesh start = polished_cube_sphere().tet;
  ASSERT_TRUE(check_mesh(start).ok);
  // Thresholds well above the defaults, so that this small mesh has many tets to try (the
  // polish left a single one below Q 0.5 and 30 degrees).
  RepairOptions o;
  o.q_below = 0.6;
  o.angle_below = 40;
  o.max_tets = 12;
  o.passes = 1;
  TetMesh m = start;
  const RepairStats s = repair_slivers(m, o);
  ::testing::Test::RecordProperty(
      "repair", std::to_string(s.nb_tried) + " tried, " + std::to_string(s.nb_inserted) +
                    " inserted, " + std::to_string(s.nb_flip_smooth) + " flips; Q_min " +
                    std::to_string(s.q_min_before) + " -> " + std::to_string(s.q_min_after));
  EXPECT_GT(s.nb_tried, 0);
  EXPECT_GT(s.nb_inserted + s.nb_flip_smooth, 0);
  const QualityStats before = quality_stats(start, "before"), after = quality_stats(m, "after");
  EXPECT_GE(after.q_min, before.q_min);
  EXPECT_GE(after.min_angle, before.min_angle);
  EXPECT_EQ(s.q_min_before, before.q_min);
  EXPECT_EQ(s.q_min_after, after.q_min);
  EXPECT_NEAR(after.q_avg, before.q_avg, 0.01);  // a few tets of many change
  EXPECT_EQ(m.nb_vertices(), start.nb_vertices() + s.nb_inserted);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_EQ(nb_not_positive(m), 0);
  EXPECT_NO_THROW(verify_optimized(start, m));
  TetMesh again = start;
  repair_slivers(again, o);
  EXPECT_EQ(again.xyz, m.xyz);
  EXPECT_EQ(again.tets, m.tets);
  EXPECT_EQ(again.tet_region, m.tet_region);
}

TEST(RepairSlivers, ToTheMeshExtremesTheAnglesStayWithinTheMeshsAndTheTimeStepIsGuarded) {
  // The last repair's rule (to_mesh_extremes) on the polished cube minus a ball, its thresholds
  // high so that many tets are tried: what changes may use the angles down to the mesh's minimum
  // and up to min(150, the mesh's maximum), each result under the time-step guard.
  const TetMesh start = polished_cube_sphere().tet;
  RepairOptions o;
  o.q_below = 0.6;
  o.angle_below = 0;
  o.max_tets = 16;
  o.passes = 1;
  o.to_mesh_extremes = true;
  o.dt_guard = time_step_guard(start, 1.0);
  TetMesh m = start;
  const RepairStats s = repair_slivers(m, o);
  ::testing::Test::RecordProperty(
      "repair", std::to_string(s.nb_tried) + " tried, " + std::to_string(s.nb_inserted) +
                    " inserted, " + std::to_string(s.nb_flip_smooth) + " other; Q_min " +
                    std::to_string(s.q_min_before) + " -> " + std::to_string(s.q_min_after));
  EXPECT_GT(s.nb_inserted + s.nb_flip_smooth, 0);
  const QualityStats before = quality_stats(start, "before"), after = quality_stats(m, "after");
  EXPECT_GE(after.q_min, before.q_min);
  EXPECT_GE(after.min_angle, before.min_angle);
  EXPECT_LE(after.max_angle, before.max_angle);
  EXPECT_GE(min_time_step(m), min_time_step(start));
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_EQ(nb_not_positive(m), 0);
  EXPECT_NO_THROW(verify_optimized(start, m));
  // It does what the default rule does on these tets and more: a higher minimum Q.
  RepairOptions strict = o;
  strict.to_mesh_extremes = false;
  TetMesh d = start;
  repair_slivers(d, strict);
  EXPECT_GT(after.q_min, quality_stats(d, "default rule").q_min);
  TetMesh again = start;
  repair_slivers(again, o);
  EXPECT_EQ(again.xyz, m.xyz);
  EXPECT_EQ(again.tets, m.tets);
}

TEST(RepairSlivers, EveryPlacementEndsNoLowerThanTheBestPairBeforeItsPlacement) {
  // With every_placement each (point, cavity) pair of the insertion is polished, placed and
  // judged: the pair the default picks is among them, so the one sliver of the micro-case ends
  // at least as high, with the same invariants.
  RepairOptions o;
  o.to_mesh_extremes = true;
  o.angle_ceiling = 180;
  const TetMesh start = locked_sliver(0.02);
  TetMesh one = start, every = start;
  const RepairStats s1 = repair_slivers(one, o);
  o.every_placement = true;
  const RepairStats s2 = repair_slivers(every, o);
  ::testing::Test::RecordProperty(
      "q_min", std::to_string(s1.q_min_after) + " / " + std::to_string(s2.q_min_after));
  EXPECT_GE(s2.nb_inserted, 1);
  EXPECT_GE(global_min_quality(every, Measure::kQ), global_min_quality(one, Measure::kQ));
  EXPECT_GE(global_min_quality(every, Measure::kMinAngle),
            global_min_quality(start, Measure::kMinAngle));
  EXPECT_TRUE(check_mesh(every).ok);
  EXPECT_EQ(nb_not_positive(every), 0);
  EXPECT_EQ(constrained_triples(every), constrained_triples(start));
  EXPECT_NO_THROW(verify_optimized(start, every));
}

TEST(RepairSlivers, ThePipelinesPolishEndsWithItAndVerifiesTheResult) {
  // The same run with the repair (the default): its minima are at least those without it (the
  // repair runs last), the run's own verify_optimized passed, the result is reproducible.
  MeshData a = testing::cube_sphere(0.14, 0.1), b = a;
  OptimizeOptions o;
  o.max_iterations = 10;
  o.auto_refine = false;  // the same path as polished_cube_sphere's (no refined run kept)
  ASSERT_TRUE(o.polish_repair);
  const OptimizeResult r = optimize(a, o);
  optimize(b, o);
  const QualityStats& without = quality_stats(polished_cube_sphere().tet, "without");
  EXPECT_GE(r.after.q_min, without.q_min);
  EXPECT_GE(r.after.min_angle, without.min_angle);
  EXPECT_EQ(a.tet.xyz, b.tet.xyz);
  EXPECT_EQ(a.tet.tets, b.tet.tets);
  EXPECT_GE(a.tet.nb_vertices(), polished_cube_sphere().tet.nb_vertices());
}

}  // namespace
}  // namespace cvtmesh
