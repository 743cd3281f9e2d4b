#include "core/cvt/lloyd3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <utility>

#include "core/cvt/lloyd3_check.h"
#include "core/cvt/voronoi_cell3.h"
#include "core/geometry/vec3.h"
#include "core/io/read_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/verify_mesh.h"
#include "core/quality/quality_stats.h"
#include "core/util/error.h"
#include "tests/support/test_meshes.h"
#include "tests/support/thread_counts.h"

namespace cvtmesh {
namespace {

TEST(Lloyd3, BccLatticeVertexIsItsOwnCentroid) {
  const double a = 1.0;
  TetMesh m = testing::delaunay_of_points(testing::bcc_lattice(4, a));
  ASSERT_TRUE(check_mesh(m).ok);
  const auto uniform = make_uniform_sizing3(a);
  const CellCentroids c = voronoi_centroids_3d(m, *uniform);
  int checked = 0;
  for (int v = 0; v < m.nb_vertices(); ++v) {
    const double* p = m.point(v);
    // Far enough from the box that the truncated octahedron is not clipped.
    bool deep = true;
    for (int d = 0; d < 3; ++d) deep &= p[d] > 1.2 * a && p[d] < 2.8 * a;
    if (!deep) continue;
    ++checked;
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(c.centroid[3 * v + d], p[d], 1e-12) << v;
    // The BCC Voronoi cell is a truncated octahedron of volume a^3 / 2.
    EXPECT_NEAR(c.mass[v], 0.5 * a * a * a, 1e-12);
  }
  EXPECT_GE(checked, 8);
}

TEST(Lloyd3, ClippedCellCentroidMatchesMonteCarloNearestGenerator) {
  // Unit cube corners (fixed) and a few interior generators near the faces: their Voronoi cells
  // are cut by the cube. The mesh is the Delaunay tetrahedralization, so the restricted cell of a
  // generator is {x in cube : nearest generator is it}. Compare with sampling.
  std::vector<double> pts;
  for (int i = 0; i < 8; ++i)
    pts.insert(pts.end(), {double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  const double interior[][3] = {
      {0.3, 0.4, 0.12}, {0.7, 0.6, 0.85}, {0.5, 0.45, 0.5}, {0.15, 0.8, 0.6}, {0.85, 0.2, 0.4}};
  for (const auto& q : interior) pts.insert(pts.end(), q, q + 3);
  TetMesh m = testing::delaunay_of_points(pts);
  ASSERT_TRUE(check_mesh(m).ok);
  const auto uniform = make_uniform_sizing3(1.0);  // rho = 1: mass = volume
  const CellCentroids c = voronoi_centroids_3d(m, *uniform);
  const int n = m.nb_vertices();
  std::vector<double> sum(3 * n, 0.0);
  std::vector<long> count(n, 0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  const long samples = 400000;
  for (long s = 0; s < samples; ++s) {
    const double x[3] = {u(rng), u(rng), u(rng)};
    int best = 0;
    double bd = 1e300;
    for (int v = 0; v < n; ++v) {
      const double d = dist2(x, m.point(v));
      if (d < bd) bd = d, best = v;
    }
    for (int d = 0; d < 3; ++d) sum[3 * best + d] += x[d];
    ++count[best];
  }
  for (int v = 8; v < n; ++v) {
    ASSERT_GT(count[v], 1000);
    EXPECT_NEAR(c.mass[v], double(count[v]) / samples, 0.01);
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(c.centroid[3 * v + d], sum[3 * v + d] / count[v], 0.01) << v << " " << d;
  }
}

MeshData coarse_cube_sphere(bool optimized) {
  return testing::cube_sphere(0.14, 0.1, optimized);
}

std::multiset<std::tuple<int, int, int, int>> constrained_set(const TetMesh& m) {
  std::multiset<std::tuple<int, int, int, int>> s;
  for (int f = 0; f < m.nb_tris(); ++f) {
    int k[3] = {m.tris[3 * f], m.tris[3 * f + 1], m.tris[3 * f + 2]};
    std::sort(k, k + 3);
    s.insert({k[0], k[1], k[2], m.tri_surface[f]});
  }
  return s;
}

TEST(Lloyd3, EnergyNeverIncreasesAndInvariantsHoldOnCubeSphere) {
  for (double omega : {1.0, 1.7}) {
    MeshData d = coarse_cube_sphere(false);
    const TetMesh input = d.tet;
    Lloyd3Options o;
    o.lloyd.max_iterations = 8;
    o.lloyd.tolerance = 0;
    o.relaxation = omega;
    o.sizing = std::shared_ptr<const SizingField3>(make_uniform_sizing3(0.12).release());
    std::vector<double> energy;
    lloyd_optimize_3d(d.tet, o, [&](const LloydStep& s) {
      energy.push_back(s.energy);
      // check_mesh around every iteration is done inside; here the mesh is valid again.
    });
    ASSERT_EQ(energy.size(), 8u);
    for (std::size_t i = 1; i < energy.size(); ++i)
      EXPECT_LE(energy[i], energy[i - 1] * (1 + 1e-12)) << omega << " " << i;
    EXPECT_LT(energy.back(), energy.front());
    const MeshCheck mc = check_mesh(d.tet);
    EXPECT_TRUE(mc.ok);
    EXPECT_EQ(mc.nb_inverted, 0);
    EXPECT_EQ(constrained_set(d.tet), constrained_set(input));
    for (int v = 0; v < input.nb_vertices(); ++v)
      if (input.vclass[v].dim < 3)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(d.tet.point(v)[k], input.point(v)[k]);
    const auto vb = region_volumes(input), va = region_volumes(d.tet);
    ASSERT_EQ(vb.size(), va.size());
    for (std::size_t i = 0; i < vb.size(); ++i)
      EXPECT_NEAR(va[i].second, vb[i].second, 1e-12 * vb[i].second);
    EXPECT_NO_THROW(verify_optimized(input, d.tet));
  }
}

TEST(Lloyd3, MeshSizingKeepsGradingAndImprovesQuality) {
  MeshData d = coarse_cube_sphere(false);
  const double q0 = quality_stats(d.tet, "").q_avg;
  Lloyd3Options o;
  o.lloyd.max_iterations = 10;
  o.relaxation = 1.7;
  lloyd_optimize_3d(d.tet, o);
  EXPECT_GT(quality_stats(d.tet, "").q_avg, q0 + 0.02);
  // Grading: edges near the ball stay shorter than edges far from it.
  double near = 0, far = 0;
  int nn = 0, nf = 0;
  for (int t = 0; t < d.tet.nb_tets(); ++t)
    for (const auto& e : kTetEdge) {
      const double* a = d.tet.point(d.tet.tets[4 * t + e[0]]);
      const double* b = d.tet.point(d.tet.tets[4 * t + e[1]]);
      const double mid[3] = {(a[0] + b[0]) / 2 - 0.5, (a[1] + b[1]) / 2 - 0.5,
                             (a[2] + b[2]) / 2 - 0.5};
      const double r = std::sqrt(mid[0] * mid[0] + mid[1] * mid[1] + mid[2] * mid[2]);
      const double l = std::sqrt(dist2(a, b));
      if (r < 0.32)
        near += l, ++nn;
      else if (r > 0.6)
        far += l, ++nf;
    }
  ASSERT_GT(nn, 0);
  ASSERT_GT(nf, 0);
  EXPECT_LT(near / nn, far / nf);
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

TEST(Lloyd3, AndersonAcceleratedAcceptedEnergiesNeverIncrease) {
  MeshData d = testing::cube_sphere(0.14, 0.1);
  Lloyd3Options o;
  o.lloyd.max_iterations = 10;
  o.lloyd.tolerance = 0;
  o.relaxation = 1.5;
  o.anderson_depth = 5;
  std::vector<double> accepted;
  int restarts = 0;
  lloyd_optimize_3d(d.tet, o, [&](const LloydStep& s) {
    if (s.restarted) {
      ++restarts;
      ASSERT_FALSE(accepted.empty());
      EXPECT_GT(s.energy, accepted.back());  // a restart happens only when the energy rose
    } else {
      accepted.push_back(s.energy);
    }
  });
  ASSERT_GE(accepted.size(), 5u);
  for (std::size_t i = 1; i < accepted.size(); ++i)
    EXPECT_LE(accepted[i], accepted[i - 1] * (1 + 1e-12));
  EXPECT_TRUE(check_mesh(d.tet).ok);
}

// L-BFGS on the CVT energy (Lloyd3Options::lbfgs_memory): every accepted configuration has an
// energy no higher than the previous accepted one (rejected line-search trials are flagged), the
// mesh stays valid, and it reaches the energy plain Lloyd has after N iterations in far fewer.
TEST(Lloyd3, LbfgsAcceptedEnergiesNeverIncreaseAndBeatPlainLloyd) {
  const MeshData init = testing::cube_sphere(0.14, 0.1);
  const int n_plain = 30;
  TetMesh plain = init.tet;
  Lloyd3Options po;
  po.lloyd.max_iterations = n_plain;
  po.lloyd.tolerance = 0;
  std::vector<double> plain_energy;
  lloyd_optimize_3d(plain, po, [&](const LloydStep& s) { plain_energy.push_back(s.energy); });
  ASSERT_EQ(plain_energy.size(), static_cast<std::size_t>(n_plain));

  TetMesh m = init.tet;
  Lloyd3Options o = po;
  o.lbfgs_memory = 5;
  std::vector<double> accepted, all;
  lloyd_optimize_3d(m, o, [&](const LloydStep& s) {
    all.push_back(s.energy);
    if (!s.restarted) accepted.push_back(s.energy);
  });
  ASSERT_EQ(all.size(), static_cast<std::size_t>(n_plain));
  // The first step is Lloyd's (taken whole); after it every accepted trial passed Armijo.
  for (std::size_t i = 2; i < accepted.size(); ++i)
    EXPECT_LE(accepted[i], accepted[i - 1]) << "accepted step " << i;
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems.front());
  int reached = -1;
  for (std::size_t i = 0; i < all.size() && reached < 0; ++i)
    if (all[i] <= plain_energy.back()) reached = static_cast<int>(i) + 1;
  std::printf(
      "plain Lloyd energy after %d iterations %.9g; L-BFGS reaches it at %d, ends at %.9g\n",
      n_plain, plain_energy.back(), reached, all.back());
  ASSERT_GT(reached, 0);
  EXPECT_LE(reached, n_plain / 2);
  EXPECT_LT(all.back(), plain_energy.back());
}

TEST(Lloyd3, SameResultForAnyThreadCount) {
  const MeshData init = testing::cube_sphere(0.14, 0.1);
  const auto results = testing::for_each_thread_count(
      [&init] {
        TetMesh m = init.tet;
        Lloyd3Options o;
        o.lloyd.max_iterations = 4;
        o.anderson_depth = 5;
        o.relaxation = 1.5;
        lloyd_optimize_3d(m, o);
        return m;
      },
      {1, 2});
  EXPECT_EQ(results[0].xyz, results[1].xyz);  // bitwise
  EXPECT_EQ(results[0].tets, results[1].tets);
}

// The pipeline shares one set of cell buffers between its CVT phases (Lloyd3Options::
// cell_buffers): a run on buffers left by a run on another mesh -- a smaller one first (the
// buffers grow), then a larger one (they are reused) -- gives the mesh a run on its own buffers
// gives, bit for bit.
TEST(Lloyd3, SharedCellBuffersGiveTheSameMeshAsOwnBuffers) {
  const MeshData small = testing::cube_sphere(0.2, 0.15), large = testing::cube_sphere(0.14, 0.1);
  ASSERT_LT(small.tet.nb_tets(), large.tet.nb_tets());
  auto run = [](const TetMesh& input, Lloyd3CellBuffers* buffers) {
    TetMesh m = input;
    Lloyd3Options o;
    o.lloyd.max_iterations = 3;
    o.lloyd.tolerance = 0;
    o.lbfgs_memory = 5;
    o.cell_buffers = buffers;
    lloyd_optimize_3d(m, o);
    return m;
  };
  const TetMesh own_small = run(small.tet, nullptr), own_large = run(large.tet, nullptr);
  Lloyd3CellBuffers shared;
  const TetMesh shared_small = run(small.tet, &shared);
  const TetMesh shared_large = run(large.tet, &shared);
  const TetMesh shared_small_again = run(small.tet, &shared);
  for (const auto& [own, other] :
       {std::pair{&own_small, &shared_small}, std::pair{&own_large, &shared_large},
        std::pair{&own_small, &shared_small_again}}) {
    EXPECT_EQ(own->xyz, other->xyz);  // bitwise
    EXPECT_EQ(own->tets, other->tets);
  }
}

// The check after every Lloyd move (lloyd3_check.h): a valid mesh passes; one whose interior
// vertex lost all its tets (a hole) is refused, naming the vertex, whatever the thread count.
TEST(Lloyd3, CheckRefusesAnInteriorVertexInNoTet) {
  const MeshData d = testing::cube_sphere(0.2, 0.15);
  EXPECT_NO_THROW(verify_lloyd3_mesh(d.tet, false));
  EXPECT_NO_THROW(verify_lloyd3_mesh(d.tet, true));
  int v = -1;
  for (int w = 0; w < d.tet.nb_vertices() && v < 0; ++w)
    if (d.tet.vclass[w].dim == 3) v = w;
  ASSERT_GE(v, 0);
  TetMesh m = d.tet;
  for (int t = 0; t < m.nb_tets(); ++t)
    for (int k = 0; k < 4; ++k)
      if (m.tets[4 * t + k] == v) {
        m.tets[4 * t] = -1;
        break;
      }
  testing::ThreadCountGuard guard;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    try {
      verify_lloyd3_mesh(m, false);
      ADD_FAILURE() << "no error with " << threads << " threads";
    } catch (const InvariantError& e) {
      EXPECT_NE(std::string(e.what()).find("interior vertex " + std::to_string(v) + " outside"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace cvtmesh
