// The time-step guard of the polish (core/quality/time_step_guard.h) and --objective dt: the
// nodal sums against the assembled matrices, the nodal step as an upper bound of the global step,
// and every guarded operator keeping the mesh's smallest element and nodal steps.
#include "core/quality/time_step_guard.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/mesh/check_mesh.h"
#include "core/pipeline/optimize.h"
#include "core/pipeline/option_schema.h"
#include "core/quality/explicit_time_step.h"
#include "core/quality/p1_system.h"
#include "core/quality/vertex_time_step.h"
#include "core/smoothing/smooth_laplacian.h"
#include "core/smoothing/smooth_maxmin3.h"
#include "core/swap/swap_slivers.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

double min_nodal(const TetMesh& m) {
  const VertexTimeSteps s = vertex_time_steps(m);
  double r = std::numeric_limits<double>::infinity();
  for (int v = 0; v < m.nb_vertices(); ++v) r = std::min(r, s.dt(v));
  return r;
}

TetMesh init_mesh() {
  return testing::cube_sphere(0.2, 0.12).tet;
}

TEST(TimeStepGuard, NodalSumsAreTheMatrixDiagonalAndAnUpperBound) {
  const TetMesh m = init_mesh();
  const P1System s = p1_system(m);
  const VertexTimeSteps vs = vertex_time_steps(m);
  double nodal = std::numeric_limits<double>::infinity();
  for (int v = 0; v < m.nb_vertices(); ++v) {
    double kii = 0;
    for (long k = s.row_ptr[v]; k < s.row_ptr[v + 1]; ++k)
      if (s.col[k] == v) kii = s.val[k];
    ASSERT_NEAR(vs.kdiag[v], kii, 1e-12 * std::fabs(kii));
    ASSERT_NEAR(vs.mass[v], s.mass[v], 1e-12 * s.mass[v]);
    nodal = std::min(nodal, vs.dt(v));
  }
  // Rayleigh: lambda_max >= K_jj / m_j, so the global step is at most the smallest nodal step;
  // Irons: at least the smallest element step.
  const double dt = explicit_time_step(s, 1e-6).time_step;
  EXPECT_LE(dt, nodal * (1 + 1e-6));
  EXPECT_GE(dt, min_time_step(m));
}

TEST(TimeStepGuard, ChangeOfAMoveMatchesTheRecomputedSums) {
  TetMesh m = init_mesh();
  VertexTimeSteps vs = vertex_time_steps(m);
  // Move one interior vertex a little and account for it through VertexStepChange.
  int v = 0;
  while (m.vclass[v].dim < 3) ++v;
  VertexStepChange ch;
  std::vector<int> star;
  for (int t = 0; t < m.nb_tets(); ++t)
    for (int k = 0; k < 4; ++k)
      if (m.tets[4 * t + k] == v) star.push_back(t);
  for (int t : star) ch.add(m, &m.tets[4 * t], -1);
  m.point(v)[0] += 1e-3;
  for (int t : star) ch.add(m, &m.tets[4 * t], +1);
  ch.apply(vs);
  const VertexTimeSteps fresh = vertex_time_steps(m);
  for (int w = 0; w < m.nb_vertices(); ++w) {
    EXPECT_NEAR(vs.kdiag[w], fresh.kdiag[w], 1e-9 * fresh.kdiag[w]);
    EXPECT_NEAR(vs.mass[w], fresh.mass[w], 1e-9 * fresh.mass[w]);
  }
}

// The guarded operators with the strict guard (floors +inf): the mesh's smallest element step
// and smallest nodal step never fall.
TEST(TimeStepGuard, GuardedOperatorsKeepTheSmallestSteps) {
  TimeStepGuard strict;
  strict.on = true;
  {
    TetMesh m = init_mesh();
    const double e0 = min_time_step(m), n0 = min_nodal(m);
    SmoothOptions so;
    so.passes = 3;
    so.dt_guard = strict;
    const SmoothStats st = smooth_laplacian(m, so);
    EXPECT_GT(st.nb_moved + st.nb_half, 0);
    EXPECT_GE(min_time_step(m), e0);
    EXPECT_GE(min_nodal(m), n0 * (1 - 1e-12));
    // Without the guard the smoothing lowers the smallest nodal step here: the guard matters.
    TetMesh u = init_mesh();
    so.dt_guard = TimeStepGuard{};
    smooth_laplacian(u, so);
    EXPECT_LT(min_nodal(u), n0);
  }
  {
    TetMesh m = init_mesh();
    const double e0 = min_time_step(m), n0 = min_nodal(m);
    MaxMinOptions mo;
    mo.dt_guard = strict;
    smooth_maxmin3(m, mo);
    EXPECT_GE(min_time_step(m), e0);
    EXPECT_GE(min_nodal(m), n0 * (1 - 1e-12));
  }
  {
    TetMesh m = init_mesh();
    const double e0 = min_time_step(m), n0 = min_nodal(m);
    SwapOptions sw;
    sw.dt_guard = strict;
    const SwapStats st = swap_slivers(m, sw);
    EXPECT_GT(st.nb_flip23 + st.nb_flip32 + st.nb_edge_removals, 0);
    EXPECT_GE(min_time_step(m), e0);
    EXPECT_GE(min_nodal(m), n0 * (1 - 1e-12));
    EXPECT_TRUE(check_mesh(m).ok);
  }
}

TEST(TimeStepGuard, ObjectiveDtNeverLowersTheElementBound) {
  MeshData d = testing::cube_sphere(0.2, 0.12);
  const double e0 = min_time_step(d.tet);
  OptimizeOptions o;
  o.method = "smooth";
  o.objective = "dt";
  o.never_worse = false;
  const OptimizeResult r = optimize(d, o);
  // Up to the rounding of the written coordinates (16 digits).
  EXPECT_GE(min_time_step(d.tet), e0 * (1 - 1e-9));
  EXPECT_GE(r.after.q_min, 0);
  o.objective = "speed";
  EXPECT_THROW(optimize(d, o), OptionError);
}

}  // namespace
}  // namespace cvtmesh
