// RandPert / ClusPert (perturb_2d) and the `cvtmesh perturb` command.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/read_mesh.h"
#include "core/io/svg_io.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/perturb2d.h"
#include "core/quality/quality_stats.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

TriMesh2 quad(int n) {
  return read_mesh(testing::geo_path("quad.geo"), {.dim = 2, .set_numbers = {{"n", double(n)}}})
      .tri;
}

bool is_free(const TriMesh2& m, int v) {
  if (m.vclass[v].dim != 2) return false;
  for (int x : m.edges)
    if (x == v) return false;
  return true;
}

TEST(Perturb2d, RandomKeepsBoundaryValidAndIsReproducible) {
  const TriMesh2 reg = quad(10);
  TriMesh2 a = reg, b = reg, c = reg;
  const Perturb2dResult r = perturb_2d(a, {.kind = Perturbation2d::kRandom, .seed = 11});
  perturb_2d(b, {.kind = Perturbation2d::kRandom, .seed = 11});
  perturb_2d(c, {.kind = Perturbation2d::kRandom, .seed = 12});
  EXPECT_TRUE(check_mesh(a).ok);
  EXPECT_EQ(a.xy, b.xy);
  EXPECT_EQ(a.tris, b.tris);
  EXPECT_NE(a.xy, c.xy);
  int nfree = 0;
  const double h = 0.1;
  for (int v = 0; v < reg.nb_vertices(); ++v) {
    const double d = std::hypot(a.point(v)[0] - reg.point(v)[0], a.point(v)[1] - reg.point(v)[1]);
    if (is_free(reg, v)) {
      ++nfree;
      EXPECT_LE(d, 0.4 * h * (1 + 1e-9));  // default amount 0.4 of the local edge length
    } else {
      EXPECT_EQ(d, 0.0);
    }
  }
  EXPECT_EQ(r.nb_moved, nfree);
  EXPECT_LT(quality_stats(a, "").q_min, 0.9);
}

TEST(Perturb2d, ClusterPullsTowardsCentreOrHole) {
  // Quad: every free vertex ends at c + 0.5 (z - c), c the area centroid.
  const TriMesh2 reg = quad(10);
  TriMesh2 q = reg;
  const Perturb2dResult r = perturb_2d(q, {.kind = Perturbation2d::kCluster});
  EXPECT_EQ(r.attractor, "centre");
  EXPECT_EQ(r.nb_limited, 0);
  EXPECT_TRUE(check_mesh(q).ok);
  const double c[2] = {0.75, std::sqrt(3.0) / 4};  // centre of the parallelogram
  for (int v = 0; v < reg.nb_vertices(); ++v)
    if (is_free(reg, v))
      for (int k = 0; k < 2; ++k)
        EXPECT_NEAR(q.point(v)[k], c[k] + 0.5 * (reg.point(v)[k] - c[k]), 1e-12);
  // Washer: the hole is the attractor; every free vertex gets closer to the inner circle.
  const MeshData w = read_mesh(testing::geo_path("washer.geo"), {.dim = 2});
  TriMesh2 m = w.tri;
  const Perturb2dResult rw = perturb_2d(m, {.kind = Perturbation2d::kCluster, .amount = 0.6});
  EXPECT_EQ(rw.attractor, "hole");
  EXPECT_TRUE(check_mesh(m).ok);
  int closer = 0, nfree = 0;
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (is_free(w.tri, v)) {
      ++nfree;
      const double r0 = std::hypot(w.tri.point(v)[0], w.tri.point(v)[1]);
      const double r1 = std::hypot(m.point(v)[0], m.point(v)[1]);
      EXPECT_GT(r1, 1.0);  // still in the washer
      if (r1 < r0) ++closer;
    }
  EXPECT_EQ(closer, nfree);
}

TEST(Perturb2d, CliWritesMeshAndPicture) {
  const std::string dir = testing::temp_dir();
  const std::string out = dir + "/q.msh", svg = dir + "/q.svg";
  std::string log;
  const int rc = testing::run(testing::cli_path() + " perturb " + testing::geo_path("quad.geo") +
                                  " --set n=6 --random --seed 4 -o " + out + " --svg " + svg,
                              &log);
  ASSERT_EQ(rc, 0) << log;
  const MeshData d = read_mesh(out);
  ASSERT_EQ(d.dim, 2);
  EXPECT_TRUE(check_mesh(d.tri).ok);
  EXPECT_EQ(d.tri.nb_tris(), 2 * 6 * 6);
  EXPECT_LT(quality_stats(d.tri, "").q_min, 1.0);
  std::ifstream f(svg);
  std::stringstream s;
  s << f.rdbuf();
  std::size_t polygons = 0;
  for (std::size_t p = s.str().find("<polygon"); p != std::string::npos;
       p = s.str().find("<polygon", p + 1))
    ++polygons;
  EXPECT_EQ(polygons, static_cast<std::size_t>(d.tri.nb_tris()));
  EXPECT_NE(s.str().find("</svg>"), std::string::npos);
  // Exactly one of --random / --cluster.
  EXPECT_NE(testing::run(testing::cli_path() + " perturb " + testing::geo_path("quad.geo") +
                         " -o " + out),
            0);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cvtmesh
