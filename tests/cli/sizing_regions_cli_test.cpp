// Issue 15, items 6 and 7 through the CLI: `--sizing FILE` (the background sizing of the CVT
// density from a reference mesh or a .geo) and `--regions` / `--physical` (optimize only some
// volumes, the others kept exactly).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "core/io/read_mesh.h"
#include "core/quality/quality_stats.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

std::string cli() {
  return testing::cli_path();
}

// The paper's washer through the CLI, as a user runs it (issue 15, item 6): the Gmsh mesh of the
// model is the reference of the sizing, the ClusPert mesh is optimized. The target is the
// paper's Table 5 ClusPert column: avg Q >= 0.989, Q_min >= 0.85, angles in [40, 92] degrees
// (the input's own sizing keeps the cluster), with default options: 2D Lloyd runs to D < 1e-8
// (1e-5, the 3D default, stopped after ~50 iterations, far from the CVT: docs/reproduction-2d.md,
// "The washer through the CLI").
TEST(SizingCli, WasherFromClusPertReachesThePapersTable5WithTheModelsSizing) {
  const std::string dir = testing::temp_dir();
  const std::string w = dir + "/w.msh", p = dir + "/p.msh", o = dir + "/o.msh";
  std::string log;
  ASSERT_EQ(testing::run(cli() + " convert " + testing::geo_path("washer.geo") + " " + w, &log), 0)
      << log;
  ASSERT_EQ(testing::run(cli() + " perturb " + w + " --cluster -o " + p, &log), 0) << log;
  ASSERT_EQ(testing::run(cli() + " optimize " + p + " --sizing " + w + " -o " + o, &log), 0) << log;
  const MeshData d = read_mesh(o);
  ASSERT_EQ(d.dim, 2);
  const QualityStats s = quality_stats(d.tri, "");
  EXPECT_GE(s.q_avg, 0.989) << log;
  EXPECT_GE(s.q_min, 0.85) << log;
  EXPECT_GE(s.min_angle, 40.0) << log;
  EXPECT_LE(s.max_angle, 92.0) << log;
  // With the input's own sizing (the default for a mesh file) the CVT keeps the cluster: the
  // reference is what makes the difference (at the old 2D stop, 48 iterations: converging to the
  // 1000-iteration cap ends at Q_min 0.338 instead of 0.354, docs/reproduction-2d.md).
  ASSERT_EQ(testing::run(cli() + " optimize " + p + " -o " + dir +
                             "/own.msh --tolerance 1e-5 --max-iterations 100",
                         &log),
            0)
      << log;
  EXPECT_LT(quality_stats(read_mesh(dir + "/own.msh").tri, "").q_min, s.q_min);
}

// Mean edge length of the tets' edges whose midpoint is within [r0, r1) of c.
double mean_edge_in_shell(const TetMesh& m, const double c[3], double r0, double r1) {
  double sum = 0;
  long n = 0;
  for (int t = 0; t < m.nb_tets(); ++t)
    for (const auto& e : kTetEdge) {
      const double* a = m.point(m.tets[4 * t + e[0]]);
      const double* b = m.point(m.tets[4 * t + e[1]]);
      double mid = 0, len = 0;
      for (int k = 0; k < 3; ++k) {
        mid += std::pow((a[k] + b[k]) / 2 - c[k], 2);
        len += std::pow(a[k] - b[k], 2);
      }
      mid = std::sqrt(mid);
      if (mid >= r0 && mid < r1) sum += std::sqrt(len), ++n;
    }
  return n ? sum / n : 0;
}

// 3D, a reference mesh graded towards the ball (fine at the ball, coarse far from it) as the
// sizing of a nearly uniform mesh of the same domain: the CVT moves the interior vertices towards
// the ball, so the optimized mesh's edges near the ball get shorter relative to those far from
// it than with the input's own (uniform) sizing.
TEST(SizingCli, ReferenceMesh3dGradesTheOptimizedMeshLikeTheReference) {
  const std::string dir = testing::temp_dir();
  const std::string in = dir + "/in.msh", ref = dir + "/ref.msh";
  std::string log;
  const std::string geo = testing::geo_path("cube_sphere.geo");
  ASSERT_EQ(testing::run(cli() + " mesh " + geo + " --set h=0.11 --set h_ball=0.11 -o " + in, &log),
            0)
      << log;
  ASSERT_EQ(testing::run(cli() + " mesh " + geo + " --set h=0.2 --set h_ball=0.05 -o " + ref, &log),
            0)
      << log;
  // Lloyd alone (its output as it is: --allow-worse), the boundary fixed by the method.
  const std::string common = " --method cvdt --max-iterations 15 --allow-worse -q";
  ASSERT_EQ(testing::run(cli() + " optimize " + in + " --sizing " + ref + " -o " + dir +
                             "/graded.msh" + common,
                         &log),
            0)
      << log;
  ASSERT_EQ(testing::run(cli() + " optimize " + in + " -o " + dir + "/own.msh" + common, &log), 0)
      << log;
  const double c[3] = {0.5, 0.5, 0.5};
  auto ratio = [&](const std::string& path) {
    const TetMesh m = read_mesh(path).tet;
    // Near the ball (radius 0.25) vs far from it.
    return mean_edge_in_shell(m, c, 0.6, 1.0) / mean_edge_in_shell(m, c, 0.25, 0.33);
  };
  const double graded = ratio(dir + "/graded.msh"), own = ratio(dir + "/own.msh"),
               reference = ratio(ref);
  EXPECT_GT(reference, 1.5);  // the reference is graded
  EXPECT_GT(graded, own * 1.1) << "graded " << graded << ", own " << own;
}

TEST(SizingCli, MissingOrUnusableReferenceIsRefusedWithExit2NamingTheFile) {
  const std::string dir = testing::temp_dir();
  const std::string w = dir + "/w.msh";
  std::string log;
  ASSERT_EQ(testing::run(cli() + " convert " + testing::geo_path("washer.geo") + " " + w, &log), 0)
      << log;
  EXPECT_EQ(
      testing::run(cli() + " optimize " + w + " --sizing " + dir + "/nope.msh -o " + dir + "/o.msh",
                   &log),
      2)
      << log;
  EXPECT_NE(log.find("nope.msh"), std::string::npos) << log;
  EXPECT_FALSE(std::filesystem::exists(dir + "/o.msh"));
  // A 3D reference for a 2D mesh.
  EXPECT_EQ(
      testing::run(cli() + " optimize " + w + " --sizing " + testing::geo_path("cube_sphere.geo") +
                       " --set h=0.3 -o " + dir + "/o.msh",
                   &log),
      2)
      << log;
  EXPECT_NE(log.find("3D"), std::string::npos) << log;
  EXPECT_FALSE(std::filesystem::exists(dir + "/o.msh"));
}

// Elements of one region by their node tags (sorted per element), and nodes by tag.
struct RegionContent {
  std::map<std::size_t, std::array<double, 3>> nodes;
  std::vector<std::array<std::size_t, 5>> tets;  // element tag, 4 node tags
};
RegionContent region_content(const TetMesh& m, int region) {
  RegionContent c;
  for (int t = 0; t < m.nb_tets(); ++t) {
    if (m.tet_region[t] != region) continue;
    std::array<std::size_t, 5> e{m.tet_tags.empty() ? 0 : m.tet_tags[t], 0, 0, 0, 0};
    for (int k = 0; k < 4; ++k) {
      const int v = m.tets[4 * t + k];
      e[k + 1] = m.node_tags[v];
      c.nodes[m.node_tags[v]] = {m.point(v)[0], m.point(v)[1], m.point(v)[2]};
    }
    c.tets.push_back(e);
  }
  std::sort(c.tets.begin(), c.tets.end());
  return c;
}

// Item 7: the ball alone is optimized; the fluid's nodes and tets (tags, connectivity,
// coordinates) are exactly as they were; the ball improves.
TEST(RegionsCli, OnlyTheSelectedVolumeChangesAndItImproves) {
  const std::string dir = testing::temp_dir();
  const std::string in = dir + "/in.msh";
  std::string log;
  ASSERT_EQ(testing::run(cli() + " mesh " + testing::geo_path("cube_sphere.geo") +
                             " --set h=0.14 --set h_ball=0.1 --set two_regions=1 -o " + in,
                         &log),
            0)
      << log;
  const TetMesh a = read_mesh(in).tet;
  std::map<std::string, int> tag;  // physical name -> volume entity
  for (const PhysicalGroup& g : a.model.groups)
    if (g.dim == 3 && g.entities.size() == 1) tag[g.name] = g.entities[0];
  ASSERT_TRUE(tag.count("ball") && tag.count("fluid"));
  const std::vector<std::string> selections = {" --physical ball",
                                               " --regions " + std::to_string(tag["ball"])};
  for (const std::string& sel : selections) {
    const std::string out = dir + "/out.msh";
    ASSERT_EQ(
        testing::run(cli() + " optimize " + in + sel + " --max-iterations 10 -o " + out, &log), 0)
        << log;
    const TetMesh b = read_mesh(out).tet;
    const RegionContent fa = region_content(a, tag["fluid"]), fb = region_content(b, tag["fluid"]);
    EXPECT_EQ(fa.tets, fb.tets) << sel;
    EXPECT_EQ(fa.nodes, fb.nodes) << sel;
    TetMesh ball_a = a, ball_b = b;
    auto only = [](TetMesh& m, int region) {
      for (int t = 0; t < m.nb_tets(); ++t)
        if (m.tet_region[t] != region) m.tets[4 * t] = -1;
    };
    only(ball_a, tag["ball"]);
    only(ball_b, tag["ball"]);
    const QualityStats qa = quality_stats(ball_a, ""), qb = quality_stats(ball_b, "");
    EXPECT_GT(qb.q_avg, qa.q_avg) << sel;
    EXPECT_GE(qb.q_min, qa.q_min) << sel;
    EXPECT_NE(region_content(b, tag["ball"]).nodes, region_content(a, tag["ball"]).nodes) << sel;
  }
}

TEST(RegionsCli, UnknownVolumeOrGroupIsRefusedWithExit2ListingTheAvailableOnes) {
  const std::string dir = testing::temp_dir();
  const std::string in = dir + "/in.msh";
  std::string log;
  ASSERT_EQ(testing::run(cli() + " mesh " + testing::geo_path("cube_sphere.geo") +
                             " --set h=0.2 --set h_ball=0.15 --set two_regions=1 -o " + in,
                         &log),
            0)
      << log;
  EXPECT_EQ(testing::run(cli() + " optimize " + in + " --regions 99 -o " + dir + "/o.msh", &log), 2)
      << log;
  EXPECT_NE(log.find("99"), std::string::npos) << log;
  std::set<int> volumes;
  const TetMesh a = read_mesh(in).tet;
  volumes.insert(a.tet_region.begin(), a.tet_region.end());
  ASSERT_EQ(volumes.size(), 2u);
  EXPECT_NE(log.find("available volumes: " + std::to_string(*volumes.begin()) + ", " +
                     std::to_string(*volumes.rbegin())),
            std::string::npos)
      << log;
  EXPECT_EQ(testing::run(cli() + " optimize " + in + " --physical nope -o " + dir + "/o.msh", &log),
            2)
      << log;
  EXPECT_NE(log.find("'ball'"), std::string::npos) << log;
  EXPECT_NE(log.find("'fluid'"), std::string::npos) << log;
  EXPECT_EQ(testing::run(cli() + " optimize " + in + " --regions 1,x -o " + dir + "/o.msh", &log),
            2)
      << log;
  EXPECT_FALSE(std::filesystem::exists(dir + "/o.msh"));
}

}  // namespace
}  // namespace cvtmesh
