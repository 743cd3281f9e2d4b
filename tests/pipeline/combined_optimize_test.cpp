#include "core/pipeline/combined_optimize.h"

#include <gtest/gtest.h>

#include "core/mesh/build_adjacency.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/optimize.h"
#include "core/pipeline/verify_mesh.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

using testing::boundary_faces;
using testing::constrained_triples;
using testing::total_volume;
using testing::unoptimized_cube_sphere;

TEST(CombinedOptimize, RaisesAverageAndMinimumQualityOfTheUnoptimizedCubeSphere) {
  TetMesh m = unoptimized_cube_sphere();
  ASSERT_TRUE(check_mesh(m).ok);
  const TetMesh start = m;
  const auto outer = boundary_faces(m);
  const double vol = total_volume(m);
  std::vector<int> iterations;
  CombinedOptions o;
  const CombinedStats s =
      combined_optimize(m, o, [&](int it, const QualityStats&) { iterations.push_back(it); });
  const QualityStats init = quality_stats(start, "Init"), now = quality_stats(m, "CombOpt");
  ::testing::Test::RecordProperty("q_min",
                                  std::to_string(init.q_min) + " -> " + std::to_string(now.q_min));
  ::testing::Test::RecordProperty("q_avg",
                                  std::to_string(init.q_avg) + " -> " + std::to_string(now.q_avg));
  EXPECT_GT(now.q_avg, init.q_avg);
  EXPECT_GT(now.q_min, init.q_min);
  EXPECT_GT(now.min_angle, init.min_angle);  // the flips' criterion: minimal dihedral angle
  EXPECT_EQ(now.nb_inverted, 0);
  EXPECT_EQ(s.before.q_avg, init.q_avg);
  EXPECT_EQ(s.after.q_avg, now.q_avg);
  EXPECT_EQ(s.after.nb_elements, m.nb_tets());
  // One progress call per iteration, numbered from 1.
  ASSERT_EQ(static_cast<int>(iterations.size()), s.iterations);
  for (int i = 0; i < s.iterations; ++i) EXPECT_EQ(iterations[i], i + 1);
  EXPECT_TRUE(s.converged || s.iterations == o.max_iterations);
  EXPECT_GT(s.nb_moved, 0);
  EXPECT_GT(s.nb_flips, 0);
  // Invariants: valid mesh, boundary kept, boundary vertices fixed, volume conserved.
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_EQ(boundary_faces(m), outer);
  EXPECT_EQ(constrained_triples(m), constrained_triples(start));
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim < 3)
      for (int k = 0; k < 3; ++k) ASSERT_EQ(m.point(v)[k], start.point(v)[k]) << "vertex " << v;
  EXPECT_NEAR(total_volume(m), vol, 1e-12 * vol);
  EXPECT_NO_THROW(verify_optimized(start, m));  // the pipeline's own end-of-run invariants
}

TEST(CombinedOptimize, ReachedTargetsLeaveTheAverageAloneToContinue) {
  // The average never counts here (tolerance 1): without targets the iterations go on while
  // the minimum or the minimum dihedral angle rises; with targets both reached after the first
  // iteration, that iteration is the last; with targets out of reach, nothing changes.
  const TetMesh start = unoptimized_cube_sphere();
  CombinedOptions o;
  o.average_tolerance = 1;
  TetMesh free_run = start;
  const CombinedStats s0 = combined_optimize(free_run, o);
  ASSERT_GT(s0.iterations, 1);  // else the targets below could not shorten anything
  CombinedOptions reached = o;
  reached.stop_at_maxmin_targets = true;
  reached.maxmin_options.q_below = 1e-9;
  reached.maxmin_options.angle_below = 1e-9;
  TetMesh m = start;
  std::vector<QualityStats> its;
  const CombinedStats s1 =
      combined_optimize(m, reached, [&](int, const QualityStats& q) { its.push_back(q); });
  ASSERT_EQ(its.size(), 1u);
  EXPECT_GE(its[0].q_min, reached.maxmin_options.q_below);
  EXPECT_GE(its[0].min_angle, reached.maxmin_options.angle_below);
  EXPECT_EQ(s1.iterations, 1);
  EXPECT_TRUE(s1.converged);
  CombinedOptions unreachable = o;
  unreachable.stop_at_maxmin_targets = true;
  unreachable.maxmin_options.q_below = 2;  // the max-min is off here: only the targets change
  unreachable.maxmin_options.angle_below = 200;
  TetMesh m2 = start;
  const CombinedStats s2 = combined_optimize(m2, unreachable);
  EXPECT_EQ(s2.iterations, s0.iterations);
  EXPECT_EQ(m2.xyz, free_run.xyz);
  EXPECT_EQ(m2.tets, free_run.tets);
}

TEST(CombinedOptimize, ZeroIterationsLeavesTheMeshAloneAndBadOptionsThrow) {
  TetMesh m = testing::cube6();
  const TetMesh start = m;
  CombinedOptions o;
  o.max_iterations = 0;
  const CombinedStats s = combined_optimize(m, o);
  EXPECT_EQ(s.iterations, 0);
  EXPECT_EQ(m.tets, start.tets);
  EXPECT_EQ(m.xyz, start.xyz);
  o.max_iterations = -1;
  EXPECT_THROW(combined_optimize(m, o), std::invalid_argument);
  o.max_iterations = 1;
  o.swap.measure = Measure::kMaxAngle;
  EXPECT_THROW(combined_optimize(m, o), std::invalid_argument);
}

// The pipeline's polish configuration (run_polish3): Q-guarded dihedral flips, max-min smoothing,
// flips that keep the global minimum Q.
CombinedOptions polish_options() {
  CombinedOptions o;
  o.swap.use_guard = true;
  o.swap.guard_measure = Measure::kQ;
  o.swap.guard_floor = 0.4;
  o.swap.quality_threshold = 45;
  o.maxmin = true;
  o.keep_min_q = true;
  return o;
}

TEST(CombinedOptimize, MaxMinPolishNeverLowersTheMinimumQAndKeepsTheInvariants) {
  // A CVDT+SWAP mesh of a small cube_sphere: what the polish gets in the pipeline.
  MeshData d = testing::cube_sphere(0.14, 0.1);
  OptimizeOptions oo;
  oo.method = "cvdt+swap";
  oo.max_iterations = 10;
  optimize(d, oo);
  TetMesh m = d.tet;
  if (m.adj.size() != m.tets.size()) build_adjacency(m);
  ASSERT_TRUE(check_mesh(m).ok);
  const TetMesh start = m;
  const double vol = total_volume(m);
  const QualityStats init = quality_stats(start, "Init");
  std::vector<double> q_min{init.q_min};
  const CombinedStats s = combined_optimize(
      m, polish_options(), [&](int, const QualityStats& q) { q_min.push_back(q.q_min); });
  EXPECT_GT(s.nb_maxmin_moved, 0);
  // Every operator of an iteration keeps the global minimum Q: it never decreases.
  for (std::size_t i = 1; i < q_min.size(); ++i) EXPECT_GE(q_min[i], q_min[i - 1]) << i;
  const QualityStats now = quality_stats(m, "Polish");
  EXPECT_GE(now.q_min, init.q_min);
  EXPECT_EQ(now.nb_inverted, 0);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_EQ(constrained_triples(m), constrained_triples(start));
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim < 3)
      for (int k = 0; k < 3; ++k) ASSERT_EQ(m.point(v)[k], start.point(v)[k]) << "vertex " << v;
  EXPECT_NEAR(total_volume(m), vol, 1e-12 * vol);
  EXPECT_NO_THROW(verify_optimized(start, m));
  // Deterministic: the same input gives the same mesh.
  TetMesh again = start;
  combined_optimize(again, polish_options());
  EXPECT_EQ(again.xyz, m.xyz);
  EXPECT_EQ(again.tets, m.tets);
}

}  // namespace
}  // namespace cvtmesh
