// Lloyd's iteration in 2D: property tests on the paper's quad and washer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/cvt/lloyd_optimize_2d.h"
#include "core/cvt/voronoi_centroids2d.h"
#include "core/cvt/sizing_field2d.h"
#include "core/delaunay/cdt2d.h"
#include "core/geometry/tet_geometry.h"
#include "core/io/read_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/perturb2d.h"
#include "core/quality/quality_stats.h"
#include "tests/support/test_meshes.h"
#include "tests/support/thread_counts.h"

namespace cvtmesh {
namespace {

std::vector<int> fixed_vertices(const TriMesh2& m) {
  std::vector<char> on(m.nb_vertices(), 0);
  for (int v : m.edges) on[v] = 1;
  std::vector<int> f;
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim != 2 || on[v]) f.push_back(v);
  return f;
}

using testing::max_nearest_distance;

// RandPert on the regular quad mesh, then Lloyd with a uniform density: the energy never
// increases, every intermediate mesh is valid, the boundary never moves, and the iteration
// returns to the regular mesh (the regular triangular lattice is a CVT: each interior cell is a
// regular hexagon centred at its generator).
TEST(Lloyd2d, QuadEnergyDecreasesAndReturnsToRegularMesh) {
  const MeshData d =
      read_mesh(testing::geo_path("quad.geo"), {.dim = 2, .set_numbers = {{"n", 8}}});
  TriMesh2 m = d.tri;
  perturb_2d(m, {.kind = Perturbation2d::kRandom, .seed = 3});
  const TriMesh2 start = m;
  const QualityStats before = quality_stats(m, "pert");
  ASSERT_LT(before.q_min, 0.9);  // the perturbation did something
  Lloyd2dOptions o;
  o.lloyd.max_iterations = 500;
  o.lloyd.tolerance = 1e-12;
  o.sizing.kind = "uniform";
  std::vector<double> energy;
  int invalid = 0, moved_fixed = 0;
  const std::vector<int> fixed = fixed_vertices(m);
  const LloydResult r = lloyd_optimize_2d(m, o, [&](const LloydStep& s) {
    energy.push_back(s.energy);
    if (!check_mesh(m).ok) ++invalid;
    for (int v : fixed)
      if (m.point(v)[0] != start.point(v)[0] || m.point(v)[1] != start.point(v)[1]) ++moved_fixed;
  });
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(invalid, 0);
  EXPECT_EQ(moved_fixed, 0);
  ASSERT_GE(energy.size(), 2u);
  for (std::size_t k = 1; k < energy.size(); ++k)
    EXPECT_LE(energy[k], energy[k - 1] * (1 + 1e-12)) << "iteration " << k + 1;
  const double h = 1.0 / 8;
  EXPECT_LT(max_nearest_distance(m, d.tri), 1e-3 * h);
  EXPECT_GT(quality_stats(m, "cvt").q_min, 0.999);
}

// The washer (coarse), clustered towards the hole, with the analytic sizing of washer.geo:
// valid meshes throughout, boundary fixed, energy non-increasing up to the quadrature error of
// a non-constant density, and the quality improves a lot.
TEST(Lloyd2d, WasherGradedDensityProperties) {
  const double h0 = 0.16, g = 0.16;
  const MeshData d =
      read_mesh(testing::geo_path("washer.geo"), {.dim = 2, .set_numbers = {{"h0", h0}, {"g", g}}});
  TriMesh2 m = d.tri;
  perturb_2d(m, {.kind = Perturbation2d::kCluster, .seed = 1});
  const TriMesh2 start = m;
  const QualityStats before = quality_stats(m, "pert");
  Lloyd2dOptions o;
  o.lloyd.max_iterations = 150;
  o.sizing.kind = "function";
  o.sizing.function = [&](const double* x) { return h0 + g * (std::hypot(x[0], x[1]) - 1.0); };
  std::vector<double> energy;
  int invalid = 0;
  lloyd_optimize_2d(m, o, [&](const LloydStep& s) {
    energy.push_back(s.energy);
    if (!check_mesh(m).ok) ++invalid;
  });
  EXPECT_EQ(invalid, 0);
  for (int v : fixed_vertices(m)) {
    EXPECT_EQ(m.point(v)[0], start.point(v)[0]);
    EXPECT_EQ(m.point(v)[1], start.point(v)[1]);
  }
  for (std::size_t k = 1; k < energy.size(); ++k)
    EXPECT_LE(energy[k], energy[k - 1] * (1 + 1e-6)) << "iteration " << k + 1;
  const QualityStats after = quality_stats(m, "cvt");
  EXPECT_GT(after.q_min, before.q_min + 0.3);
  EXPECT_GT(after.q_avg, before.q_avg);
  EXPECT_GT(after.q_avg, quality_stats(d.tri, "gmsh").q_avg - 0.01);  // as good as Gmsh's
}

// Over-relaxed, Anderson-accelerated Lloyd (the product default of optimize()): the energies of
// the accepted configurations never increase (a rejected accelerated step is replaced by the
// plain one), the boundary never moves, and it reaches the same regular mesh.
TEST(Lloyd2d, AcceleratedKeepsAcceptedEnergiesMonotone) {
  const MeshData d =
      read_mesh(testing::geo_path("quad.geo"), {.dim = 2, .set_numbers = {{"n", 8}}});
  TriMesh2 m = d.tri;
  perturb_2d(m, {.kind = Perturbation2d::kCluster});
  const TriMesh2 start = m;
  Lloyd2dOptions o;
  o.lloyd.max_iterations = 500;
  o.lloyd.tolerance = 1e-12;
  o.sizing.kind = "uniform";
  o.relaxation = 1.5;
  o.anderson_depth = 5;
  std::vector<double> accepted;
  int invalid = 0;
  const LloydResult r = lloyd_optimize_2d(m, o, [&](const LloydStep& s) {
    if (!s.restarted) accepted.push_back(s.energy);
    if (!check_mesh(m).ok) ++invalid;
  });
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(invalid, 0);
  for (std::size_t k = 1; k < accepted.size(); ++k)
    EXPECT_LE(accepted[k], accepted[k - 1] * (1 + 1e-12)) << "accepted step " << k;
  for (int v : fixed_vertices(m)) {
    EXPECT_EQ(m.point(v)[0], start.point(v)[0]);
    EXPECT_EQ(m.point(v)[1], start.point(v)[1]);
  }
  EXPECT_LT(max_nearest_distance(m, d.tri), 1e-3 / 8);
}

// L-BFGS on the CVT energy: every step lowers F (Armijo line search; exact integrals for a
// uniform density), every mesh is valid with no inverted triangle, the boundary never moves,
// and from the perturbed quad it reaches the regular mesh in fewer iterations than Lloyd.
TEST(Lloyd2d, LbfgsLowersTheEnergyAndReturnsToRegularMesh) {
  const MeshData d =
      read_mesh(testing::geo_path("quad.geo"), {.dim = 2, .set_numbers = {{"n", 8}}});
  TriMesh2 start = d.tri;
  perturb_2d(start, {.kind = Perturbation2d::kRandom, .seed = 3});
  Lloyd2dOptions o;
  o.lloyd.max_iterations = 500;
  o.lloyd.tolerance = 1e-12;
  o.sizing.kind = "uniform";
  TriMesh2 lloyd = start;
  const LloydResult rl = lloyd_optimize_2d(lloyd, o);
  ASSERT_TRUE(rl.converged);

  o.lbfgs_memory = 7;
  TriMesh2 m = start;
  const std::vector<int> fixed = fixed_vertices(m);
  std::vector<double> energy;
  int invalid = 0, inverted = 0;
  const LloydResult r = lloyd_optimize_2d(m, o, [&](const LloydStep& s) {
    energy.push_back(s.energy);
    if (!check_mesh(m).ok) ++invalid;
    for (int t = 0; t < m.nb_tris(); ++t) {
      const int* tv = &m.tris[3 * t];
      if (tv[0] >= 0 && !(tri_area2d(m.point(tv[0]), m.point(tv[1]), m.point(tv[2])) > 0))
        ++inverted;
    }
  });
  EXPECT_TRUE(r.converged);
  EXPECT_LT(r.iterations, rl.iterations);
  EXPECT_EQ(invalid, 0);
  EXPECT_EQ(inverted, 0);
  for (int v : fixed) {
    EXPECT_EQ(m.point(v)[0], start.point(v)[0]);
    EXPECT_EQ(m.point(v)[1], start.point(v)[1]);
  }
  for (std::size_t k = 1; k < energy.size(); ++k)
    EXPECT_LE(energy[k], energy[k - 1] * (1 + 1e-12)) << "iteration " << k + 1;
  EXPECT_LT(max_nearest_distance(m, d.tri), 1e-3 / 8);
}

// Basin hopping on the coarse clustered washer: the first run is exactly plain Lloyd from the
// same start, the returned mesh's CVT energy is the lowest reached and never above Lloyd's
// converged energy, every trial mesh is valid with no inverted triangle, the boundary never
// moves, and the same seed gives the same mesh.
TEST(Lloyd2d, BasinHoppingNeverEndsAboveLloydsEnergy) {
  const double h0 = 0.16, g = 0.16;
  const MeshData d =
      read_mesh(testing::geo_path("washer.geo"), {.dim = 2, .set_numbers = {{"h0", h0}, {"g", g}}});
  TriMesh2 start = d.tri;
  perturb_2d(start, {.kind = Perturbation2d::kCluster});
  Lloyd2dOptions o;
  o.lloyd.max_iterations = 2000;
  o.lloyd.tolerance = 1e-9;
  o.sizing.kind = "function";
  o.sizing.function = [&](const double* x) { return h0 + g * (std::hypot(x[0], x[1]) - 1.0); };
  o.relaxation = 1.5;
  o.anderson_depth = 5;

  TriMesh2 plain = start;
  Lloyd2dReport plain_report;
  ASSERT_TRUE(lloyd_optimize_2d(plain, o, nullptr, &plain_report).converged);
  EXPECT_EQ(plain_report.hops, 0);
  EXPECT_EQ(plain_report.energy, plain_report.lloyd_energy);

  o.hops = 4;
  o.hop_amount = 0.4;
  o.hop_seed = 7;
  TriMesh2 m = start;
  Lloyd2dReport rep;
  const std::vector<int> fixed = fixed_vertices(m);
  int invalid = 0, inverted = 0, moved_fixed = 0, hop_steps = 0;
  lloyd_optimize_2d(
      m, o,
      [&](const LloydStep& s) {
        if (s.hop > 0) ++hop_steps;
        if (!check_mesh(m).ok) ++invalid;
        for (int t = 0; t < m.nb_tris(); ++t) {
          const int* tv = &m.tris[3 * t];
          if (tv[0] >= 0 && !(tri_area2d(m.point(tv[0]), m.point(tv[1]), m.point(tv[2])) > 0))
            ++inverted;
        }
      },
      &rep);
  EXPECT_EQ(invalid, 0);
  EXPECT_EQ(inverted, 0);
  EXPECT_GT(hop_steps, 0);
  for (int v : fixed)
    if (m.point(v)[0] != start.point(v)[0] || m.point(v)[1] != start.point(v)[1]) ++moved_fixed;
  EXPECT_EQ(moved_fixed, 0);
  EXPECT_TRUE(check_mesh(m).ok);
  // The first run is plain Lloyd from the same start.
  EXPECT_EQ(rep.lloyd_energy, plain_report.lloyd_energy);
  EXPECT_EQ(rep.lloyd_iterations, plain_report.lloyd_iterations);
  // The accepted energy: the minimum over Lloyd's and the hops', never above Lloyd's.
  ASSERT_EQ(rep.hops, 4);
  ASSERT_EQ(rep.hop_energies.size(), 4u);
  EXPECT_LE(rep.energy, plain_report.energy);
  double lowest = rep.lloyd_energy;
  for (double e : rep.hop_energies) lowest = std::min(lowest, e);
  EXPECT_EQ(rep.energy, lowest);
  // ... and it is the energy of the returned mesh.
  const SizingField2d sizing(m, o.sizing);
  double f = 0;
  for (const VoronoiCell2d& c :
       voronoi_centroids2d(m, [&](const double* x) { return sizing.density(x); }))
    f += c.energy;
  EXPECT_NEAR(f, rep.energy, 1e-12 * rep.energy);
  // Deterministic for a seed.
  TriMesh2 again = start;
  Lloyd2dReport rep2;
  lloyd_optimize_2d(again, o, nullptr, &rep2);
  EXPECT_EQ(rep2.energy, rep.energy);
  EXPECT_EQ(again.xy, m.xy);
}

// The washer's Gmsh mesh d, its ClusPert perturbation m, and the "mesh" sizing with d as the
// background (m and d share vertices but not positions).
struct WasherClusPert {
  WasherClusPert() : d(read_mesh(testing::geo_path("washer.geo"), {.dim = 2})), m(d.tri) {
    perturb_2d(m, {.kind = Perturbation2d::kCluster});
    sizing.kind = "mesh";
    sizing.background = &d.tri;
  }
  WasherClusPert(const WasherClusPert&) = delete;  // sizing points into d
  WasherClusPert& operator=(const WasherClusPert&) = delete;
  MeshData d;
  TriMesh2 m;
  SizingField2dOptions sizing;
};

// How many cells differ from b's in mass, energy or centroid (bit for bit); a and b of one size.
int cells_differing(const std::vector<VoronoiCell2d>& a, const std::vector<VoronoiCell2d>& b) {
  int differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    differ += a[i].mass != b[i].mass || a[i].energy != b[i].energy ||
              a[i].centroid[0] != b[i].centroid[0] || a[i].centroid[1] != b[i].centroid[1];
  return differ;
}

// The washer's ClusPert mesh with its Gmsh mesh as the sizing reference ("mesh" sizing): the
// cells computed by several threads are those of one thread, bit for bit; and the size at every
// quadrature-like point (the walk from the last triangle found) is the P1 interpolation in the
// background triangle that contains it, found here by brute force.
TEST(Lloyd2d, MeshSizingCellsInParallelEqualSerialAndTheLookupIsP1) {
  const WasherClusPert w;
  const MeshData& d = w.d;
  const TriMesh2& m = w.m;
  const SizingField2d sizing(m, w.sizing);
  ASSERT_TRUE(sizing.thread_safe());
  const auto density = [&](const double* x) { return sizing.density(x); };
  const auto serial = voronoi_centroids2d(m, density, false);
  const auto parallel = voronoi_centroids2d(m, density, true);
  ASSERT_EQ(serial.size(), parallel.size());
  EXPECT_EQ(cells_differing(serial, parallel), 0);
  // Vertex sizes of the background as size() computes them are not exposed: compare with the
  // P1 interpolation of size() at the background's own vertices (exact at a vertex).
  const TriMesh2& bg = d.tri;
  std::vector<double> hv(bg.nb_vertices());
  for (int v = 0; v < bg.nb_vertices(); ++v) hv[v] = sizing.size(bg.point(v));
  int wrong = 0, inside = 0;
  for (int t = 0; t < m.nb_tris(); ++t)  // points along the optimized mesh's triangles
    for (int q = 0; q < 3; ++q) {
      const int* tv = &m.tris[3 * t];
      const double w[3] = {q == 0 ? 0.6 : 0.2, q == 1 ? 0.6 : 0.2, q == 2 ? 0.6 : 0.2};
      double x[2] = {0, 0};
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 2; ++c) x[c] += w[k] * m.point(tv[k])[c];
      for (int b = 0; b < bg.nb_tris(); ++b) {
        const int* bv = &bg.tris[3 * b];
        const double* a = bg.point(bv[0]);
        const double* e = bg.point(bv[1]);
        const double* f = bg.point(bv[2]);
        const double det = (e[0] - a[0]) * (f[1] - a[1]) - (e[1] - a[1]) * (f[0] - a[0]);
        const double l1 = ((x[0] - a[0]) * (f[1] - a[1]) - (x[1] - a[1]) * (f[0] - a[0])) / det;
        const double l2 = ((e[0] - a[0]) * (x[1] - a[1]) - (e[1] - a[1]) * (x[0] - a[0])) / det;
        const double l0 = 1 - l1 - l2;
        if (std::min({l0, l1, l2}) <= 1e-9) continue;
        ++inside;
        const double want = l0 * hv[bv[0]] + l1 * hv[bv[1]] + l2 * hv[bv[2]];
        if (std::fabs(sizing.size(x) - want) > 1e-12 * want) ++wrong;
        break;
      }
    }
  EXPECT_GT(inside, m.nb_tris());
  EXPECT_EQ(wrong, 0);
}

// The cells with the sizing given as a SizingField2d (each thread's own walk, no std::function
// per quadrature point, the Delaunay triangulation given by the caller or not) are those with
// the density rho = sizing.density(x) as a function, bit for bit, for 1, 2 and 3 threads; and
// size(x, hint) is size(x) whatever the hint the walk starts from.
TEST(Lloyd2d, SizingCellsEqualTheDensityFunctionsForAnyThreadCount) {
  const WasherClusPert w;
  const MeshData& d = w.d;
  const TriMesh2& m = w.m;
  const SizingField2d sizing(m, w.sizing);
  const auto want = voronoi_centroids2d(m, [&](const double* x) { return sizing.density(x); });
  const Cdt2dResult del = cdt2d(m.xy, {});
  const auto runs = testing::for_each_thread_count([&] {
    std::vector<std::vector<VoronoiCell2d>> r;
    r.push_back(voronoi_centroids2d(m, sizing, true));
    r.push_back(voronoi_centroids2d(m, sizing, true, &del));
    r.push_back(voronoi_centroids2d(m, sizing, false));
    return r;
  });
  int differ = 0;
  for (const auto& run : runs)
    for (const auto& cells : run) {
      ASSERT_EQ(cells.size(), want.size());
      differ += cells_differing(cells, want);
    }
  EXPECT_EQ(differ, 0);
  int wrong = 0;
  const int nbg = d.tri.nb_tris();
  for (int t = 0; t < m.nb_tris(); ++t) {
    const int* tv = &m.tris[3 * t];
    double x[2] = {0, 0};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 2; ++c) x[c] += m.point(tv[k])[c] / 3;
    int hint = (t * 7919) % nbg;  // anywhere: a long walk, or the bucket scan
    wrong += sizing.size(x, hint) != sizing.size(x);
    int none = -1;
    wrong += sizing.size(x, none) != sizing.size(x);
  }
  EXPECT_EQ(wrong, 0);
  // A uniform sizing: rho = 1, the exact integrals of voronoi_centroids2d(m).
  SizingField2dOptions uo;
  uo.kind = "uniform";
  const auto exact = voronoi_centroids2d(m);
  const auto uniform = voronoi_centroids2d(m, SizingField2d(m, uo), true);
  int udiffer = 0;
  for (std::size_t i = 0; i < exact.size(); ++i)
    udiffer += exact[i].mass != uniform[i].mass || exact[i].centroid[0] != uniform[i].centroid[0];
  EXPECT_EQ(udiffer, 0);
}

}  // namespace
}  // namespace cvtmesh
