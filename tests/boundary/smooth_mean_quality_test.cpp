// The average-quality smoothing (core/boundary/smooth_mean_quality.h): the analytic gradient of Q
// is the derivative; the sum of Q rises while the minima (Q, dihedral angle, boundary triangles'
// Q) never fall; surface vertices stay on their faces (a box) and on the exact sphere (a CAD
// ball), corners never move; the mesh stays valid; the flips on the average
// (SwapOptions::sum_criterion) raise the sum less the starting mean per tet and never lower
// the minimum.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/boundary/discrete_boundary.h"
#include "core/boundary/smooth_mean_quality.h"
#include "core/boundary/verify_free_boundary.h"
#include "core/io/gmsh_cad_boundary.h"
#include "core/io/gmsh_model.h"
#include "core/io/gmsh_session.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/verify_mesh.h"
#include "core/quality/quality.h"
#include "core/quality/quality_stats.h"
#include "core/quality/time_step_guard.h"
#include "core/swap/swap_slivers.h"
#include "tests/support/box_moves.h"
#include "tests/support/test_meshes.h"
#include "tests/support/thread_counts.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

constexpr int kN = 4;  // the box [0, 4]^3, lattice spacing 1

// The box's lattice jittered within its faces and edges (test_meshes.h), deterministic.
TetMesh jittered_box(double amount) {
  return testing::jittered_box(kN, amount, 777u);
}

struct Figures {
  double sum = 0, q_min = 1e300, angle_min = 1e300, tri_min = 1e300, angle_max = 0;
};

Figures figures(const TetMesh& m) {
  Figures f;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] < 0) continue;
    const double *a = m.point(v[0]), *b = m.point(v[1]), *c = m.point(v[2]), *d = m.point(v[3]);
    const double q = tet_quality(a, b, c, d, Measure::kQ);
    f.sum += q;
    f.q_min = std::min(f.q_min, q);
    f.angle_min = std::min(f.angle_min, tet_quality(a, b, c, d, Measure::kMinAngle));
    f.angle_max = std::max(f.angle_max, tet_quality(a, b, c, d, Measure::kMaxAngle));
  }
  for (int k = 0; k < m.nb_tris(); ++k) {
    const int* v = &m.tris[3 * k];
    f.tri_min = std::min(f.tri_min,
                         tri_quality(m.point(v[0]), m.point(v[1]), m.point(v[2]), 3, Measure::kQ));
  }
  return f;
}

TEST(TetQGradient, IsTheDerivativeOfQ) {
  const double p0[4][3] = {{0.1, -0.2, 0.05}, {1.3, 0.1, -0.1}, {0.4, 0.9, 0.2}, {0.3, 0.2, 1.1}};
  for (int k = 0; k < 4; ++k) {
    double p[4][3];
    std::copy(&p0[0][0], &p0[0][0] + 12, &p[0][0]);
    const double* pp[4] = {p[0], p[1], p[2], p[3]};
    double g[3];
    tet_q_gradient(pp, k, g);
    for (int c = 0; c < 3; ++c) {
      const double h = 1e-6, x = p[k][c];
      p[k][c] = x + h;
      const double qp = tet_quality(p[0], p[1], p[2], p[3], Measure::kQ);
      p[k][c] = x - h;
      const double qm = tet_quality(p[0], p[1], p[2], p[3], Measure::kQ);
      p[k][c] = x;
      EXPECT_NEAR(g[c], (qp - qm) / (2 * h), 1e-7) << "vertex " << k << " coordinate " << c;
    }
  }
}

TEST(SmoothMeanQuality, TheSumRisesTheMinimaNeverFallAndFacesStayFlat) {
  TetMesh m = jittered_box(0.3);
  ASSERT_TRUE(check_mesh(m).ok);
  const TetMesh start = m;
  const BoundaryModel b = make_discrete_boundary(m);
  const Figures before = figures(m);
  MeanQualityOptions o;
  o.passes = 3;
  o.star_below = 1;
  const MeanQualityStats st = smooth_mean_quality(m, b, o);
  ASSERT_TRUE(check_mesh(m).ok);
  EXPECT_EQ(testing::nb_not_positive(m), 0);
  const Figures after = figures(m);
  EXPECT_GT(st.nb_moved, 0);
  EXPECT_GT(after.sum, before.sum);
  EXPECT_NEAR(st.sum_before, before.sum, 1e-9);
  EXPECT_NEAR(st.sum_after, after.sum, 1e-9);
  // The guards: nothing falls below min(its minimum before, the floor).
  EXPECT_GE(after.q_min, std::min(before.q_min, o.q_floor));
  EXPECT_GE(after.angle_min, std::min(before.angle_min, o.angle_floor));
  EXPECT_GE(after.tri_min, std::min(before.tri_min, o.tri_floor));
  const auto moved = testing::box_moves(m, start, kN);
  EXPECT_GT(moved[0], 0);  // inside
  EXPECT_GT(moved[1], 0);  // on a face
  // The end-of-run invariants of a free boundary: flat faces, so no volume change.
  VerifyOptions vo;
  vo.boundary_moves = true;
  vo.volume_tolerance = 1e-9;
  EXPECT_NO_THROW(verify_optimized(start, m, vo));
  FreeBoundaryTolerances ft;
  ft.hausdorff = 1e-9;
  EXPECT_LE(verify_free_boundary(start, m, b, ft).hausdorff.value(), 1e-9);
}

// The ceiling (stop 39): with it the maximum dihedral angle never rises while the sum does;
// without it (180) the same passes raise it (the box smoothed once, then the passes with the
// floors at 0, which leave the moves freer), so the guard is what holds it.
TEST(SmoothMeanQuality, TheMaximumDihedralAngleNeverRisesUnderTheCeiling) {
  TetMesh start = jittered_box(0.3);
  const BoundaryModel b = make_discrete_boundary(start);
  MeanQualityOptions o;
  o.star_below = 1;
  smooth_mean_quality(start, b, o);
  const Figures before = figures(start);
  o.q_floor = o.angle_floor = o.tri_floor = 0;
  o.passes = 10;
  o.max_steps = 10;
  TetMesh guarded = start, free = start;
  smooth_mean_quality(guarded, b, o);
  o.angle_ceiling = 180;
  smooth_mean_quality(free, b, o);
  ASSERT_TRUE(check_mesh(guarded).ok);
  const Figures g = figures(guarded), f = figures(free);
  EXPECT_GT(g.sum, before.sum);
  EXPECT_LE(g.angle_max, before.angle_max);
  EXPECT_GT(f.angle_max, before.angle_max) << "the box no longer shows the guard: pick another";
}

TEST(SmoothMeanQuality, InteriorOnlyLeavesTheBoundaryAndAGoodMeshIsLeftAlone) {
  TetMesh m = jittered_box(0.3);
  const TetMesh start = m;
  MeanQualityOptions o;
  o.star_below = 1;
  const MeanQualityStats st = smooth_mean_quality(m, BoundaryModel{}, o);
  EXPECT_GT(st.nb_moved, 0);
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (start.vclass[v].dim < 3)
      for (int d = 0; d < 3; ++d) EXPECT_EQ(m.point(v)[d], start.point(v)[d]) << v;
  // No star's mean below 0: nothing is tried.
  o.star_below = 0;
  TetMesh again = start;
  EXPECT_EQ(smooth_mean_quality(again, BoundaryModel{}, o).nb_tried, 0);
  EXPECT_EQ(again.xyz, start.xyz);
}

TEST(SmoothMeanQuality, SurfaceVerticesOfACadBallStayOnTheSphereTo1e12) {
  const std::string geo = testing::temp_dir() + "/mean_ball.geo";
  {
    std::ofstream f(geo);
    f << "SetFactory(\"OpenCASCADE\");\nSphere(1) = {0.1, 0.2, 0.3, 1};\n"
         "Mesh.MeshSizeMax = 0.35;\nMesh.MeshSizeMin = 0.35;\n";
  }
  GmshSession session;
  gmsh::open(geo);
  gmsh::model::mesh::generate(3);
  MeshData d = mesh_from_gmsh(3, "ball");
  TetMesh& m = d.tet;
  const TetMesh start = m;
  const BoundaryModel b = make_gmsh_cad_boundary(m);
  const Figures before = figures(m);
  MeanQualityOptions o;
  o.star_below = 1;
  o.hausdorff = 0.05;
  const MeanQualityStats st = smooth_mean_quality(m, b, o);
  ASSERT_TRUE(check_mesh(m).ok);
  EXPECT_GT(figures(m).sum, before.sum);
  int moved_surface = 0;
  for (int v = 0; v < start.nb_vertices(); ++v) {
    const double *p = m.point(v), *p0 = start.point(v);
    if (p[0] == p0[0] && p[1] == p0[1] && p[2] == p0[2]) continue;
    ASSERT_NE(start.vclass[v].dim, 0) << "a CAD point moved";
    if (start.vclass[v].dim == 3) continue;
    moved_surface += start.vclass[v].dim == 2;
    const double r = std::sqrt((p[0] - 0.1) * (p[0] - 0.1) + (p[1] - 0.2) * (p[1] - 0.2) +
                               (p[2] - 0.3) * (p[2] - 0.3));
    EXPECT_LE(std::fabs(r - 1), 1e-12) << v;
  }
  EXPECT_GT(st.nb_moved, 0);
  EXPECT_GT(moved_surface, 0);
}

TEST(SwapSumCriterion, TheSumLessTheStartMeanRisesAndTheMinimumNeverFalls) {
  TetMesh m = jittered_box(0.45);
  const QualityStats before = quality_stats(m, "");
  SwapOptions so;
  so.sum_criterion = true;
  const SwapStats st = swap_slivers(m, so);
  ASSERT_TRUE(check_mesh(m).ok);
  EXPECT_EQ(testing::nb_not_positive(m), 0);
  const QualityStats after = quality_stats(m, "");
  EXPECT_GT(st.nb_flip23 + st.nb_flip32 + st.nb_edge_removals, 0);
  // What each swap raises: the sum less the starting mean per tet.
  const double m0 = before.q_avg;
  EXPECT_GT(after.q_avg * after.nb_elements - m0 * after.nb_elements,
            before.q_avg * before.nb_elements - m0 * before.nb_elements);
  EXPECT_GE(after.q_min, before.q_min);
}

// The interior vertices move colour by colour in parallel, the nodal sums of the time-step guard
// judged again in vertex order after each colour: the same points and counts for any number of
// threads, with and without the guard (cube_sphere, ~4k interior vertices: its first colours hold
// several hundred, above the one-thread cut).
TEST(SmoothMeanQuality, SameResultForAnyNumberOfThreads) {
  for (const bool dt_guard : {false, true}) {
    const auto runs = testing::for_each_thread_count([dt_guard] {
      TetMesh m = testing::unoptimized_cube_sphere();
      MeanQualityOptions o;
      if (dt_guard) o.dt_guard = time_step_guard(m, 1.0);
      const MeanQualityStats st = smooth_mean_quality(m, BoundaryModel{}, o);
      return std::make_pair(std::move(m), st);
    });
    const MeanQualityStats& first = runs[0].second;
    EXPECT_GT(first.nb_moved, 1000);
    EXPECT_GT(first.sum_after, first.sum_before);
    for (std::size_t k = 1; k < runs.size(); ++k) {
      SCOPED_TRACE("dt_guard " + std::to_string(dt_guard) + ", run " + std::to_string(k));
      const auto& [m, st] = runs[k];
      EXPECT_EQ(m.xyz, runs[0].first.xyz);
      EXPECT_EQ(st.nb_tried, first.nb_tried);
      EXPECT_EQ(st.nb_moved, first.nb_moved);
      EXPECT_EQ(st.nb_steps, first.nb_steps);
    }
  }
}

}  // namespace
}  // namespace cvtmesh
