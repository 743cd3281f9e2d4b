// End-to-end runs of `cvtmesh optimize`, `mesh`, `compare` and `check` on the bundled model.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/io/histogram_png.h"
#include "core/io/read_mesh.h"
#include "core/pipeline/verify_mesh.h"
#include "core/quality/quality_stats.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

const std::string kCoarse = " --set h=0.14 --set h_ball=0.1";

TEST(OptimizeCli, MeshThenOptimizeWritesAValidBetterMeshWithQualityViews) {
  const std::string dir = testing::temp_dir();
  const std::string init = dir + "/init.msh", out = dir + "/out.msh";
  std::string log;
  ASSERT_EQ(testing::run(testing::cli_path() + " mesh " + testing::geo_path("cube_sphere.geo") +
                             kCoarse + " -o " + init,
                         &log),
            0)
      << log;
  ASSERT_EQ(testing::run(testing::cli_path() + " optimize " + init + " -o " + out +
                             " --method cvdt --max-iterations 6 --quality",
                         &log),
            0)
      << log;
  // Progress lines on stderr: iteration, D, energy, Q.
  EXPECT_NE(log.find("lloyd"), std::string::npos);
  EXPECT_NE(log.find("energy"), std::string::npos);
  const MeshData a = read_mesh(init), b = read_mesh(out);
  EXPECT_NO_THROW(verify_optimized(a.tet, b.tet));
  EXPECT_GT(quality_stats(b.tet, "").q_avg, quality_stats(a.tet, "").q_avg);
  // The quality views are in the file.
  std::string content;
  ASSERT_EQ(testing::run("grep -c '\\$ElementData' " + out, &content), 0);
  EXPECT_EQ(std::stoi(content), 3);
  ASSERT_EQ(testing::run(testing::cli_path() + " check " + out, &log), 0) << log;
  EXPECT_NE(log.find(": ok"), std::string::npos);
}

TEST(OptimizeCli, UnknownMethodAndBadOptionsFailCleanly) {
  const std::string dir = testing::temp_dir();
  std::string log;
  EXPECT_NE(testing::run(testing::cli_path() + " optimize " + testing::geo_path("cube_sphere.geo") +
                             kCoarse + " -o " + dir + "/x.msh --method nonsense",
                         &log),
            0);
  EXPECT_NE(log.find("nonsense"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.msh"));
  EXPECT_NE(testing::run(testing::cli_path() + " optimize " + testing::geo_path("cube_sphere.geo") +
                             " -o " + dir + "/x.msh --relaxation 3",
                         &log),
            0);
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.msh"));
}

// `optimize --parts`: a 2D mesh and more parts than tets are refused (exit 2) with the file
// named, nothing written; a 3D run writes a mesh that `check` accepts.
TEST(OptimizeCli, PartsRefusesA2DMeshAndMorePartsThanTetsAndWritesAValidMesh) {
  const std::string dir = testing::temp_dir();
  std::string log;
  const std::string quad = testing::geo_path("quad.geo");
  EXPECT_EQ(
      testing::run(testing::cli_path() + " optimize " + quad + " -o " + dir + "/x.msh --parts 2",
                   &log),
      2)
      << log;
  EXPECT_NE(log.find("quad.geo' is not a 3D tet mesh"), std::string::npos) << log;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.msh"));
  const std::string init = dir + "/init.msh";
  ASSERT_EQ(testing::run(testing::cli_path() + " mesh " + testing::geo_path("cube_sphere.geo") +
                             kCoarse + " -o " + init,
                         &log),
            0)
      << log;
  EXPECT_EQ(
      testing::run(
          testing::cli_path() + " optimize " + init + " -o " + dir + "/x.msh --parts 100000", &log),
      2)
      << log;
  EXPECT_NE(log.find("fewer than the parts"), std::string::npos) << log;
  EXPECT_NE(log.find("init.msh"), std::string::npos) << log;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.msh"));
  ASSERT_EQ(testing::run(testing::cli_path() + " optimize " + init + " -o " + dir +
                             "/p.msh --parts 3 --rounds 2",
                         &log),
            0)
      << log;
  EXPECT_NE(log.find("round 2: 3 parts"), std::string::npos) << log;
  EXPECT_EQ(testing::run(testing::cli_path() + " check " + dir + "/p.msh", &log), 0) << log;
}

TEST(OptimizeCli, CompareHasTheInitAndCvdtColumnsAndTheBaselines) {
  std::string log;
  ASSERT_EQ(testing::run(testing::cli_path() + " compare " + testing::geo_path("cube_sphere.geo") +
                             kCoarse + " --max-iterations 4 --format markdown",
                         &log),
            0)
      << log;
  for (const char* col :
       {"Init", "CVDT", "Gmsh optimize", "TetGen -q -O", "Netgen optimize", "CGAL remeshing"})
    EXPECT_NE(log.find(col), std::string::npos) << col;
  EXPECT_NE(log.find("| average quality |"), std::string::npos);
}

// The paper's columns are the methods' own results, not the never-worse fallback of optimize:
// compare's CVDT mesh is what `optimize --method cvdt --allow-worse` makes of the same Init.
TEST(OptimizeCli, CompareShowsTheMethodsThemselves) {
  const std::string dir = testing::temp_dir();
  std::string log;
  ASSERT_EQ(testing::run(testing::cli_path() + " compare " + testing::geo_path("cube_sphere.geo") +
                             kCoarse + " --max-iterations 4 --no-baselines --save " + dir,
                         &log),
            0)
      << log;
  ASSERT_EQ(testing::run(testing::cli_path() + " optimize " + dir + "/init.msh -o " + dir +
                             "/own.msh --method cvdt --allow-worse --max-iterations 4 -q",
                         &log),
            0)
      << log;
  std::string a, b;
  ASSERT_EQ(testing::run(testing::cli_path() + " stats " + dir + "/cvdt.msh", &a), 0) << a;
  ASSERT_EQ(testing::run(testing::cli_path() + " stats " + dir + "/own.msh", &b), 0) << b;
  auto row = [](const std::string& t, const std::string& name) {
    const auto at = t.find(name);
    if (at == std::string::npos) return std::string("missing");
    const std::string line = t.substr(at, t.find('\n', at) - at);
    return line.substr(line.find_last_of(' ') + 1);  // the value (the columns' widths differ)
  };
  for (const char* r : {"Q_min", "average quality", "min dihedral angle"})
    EXPECT_EQ(row(a, r), row(b, r)) << r;
  // --save also wrote the columns' histograms: SVG always, PNG when rsvg-convert is installed.
  EXPECT_TRUE(std::filesystem::exists(dir + "/histogram.svg"));
  if (!histogram_png_rasterizer().empty()) {
    std::ifstream png(dir + "/histogram.png", std::ios::binary);
    char sig[8] = {};
    ASSERT_TRUE(png.read(sig, 8)) << "no " << dir << "/histogram.png";
    EXPECT_EQ(std::string(sig + 1, 3), "PNG");
  }
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

TEST(OptimizeCli, BenchPrintsOneSuccessfulRowPerMeasurement) {
  std::string out;
  ASSERT_EQ(
      testing::run(
          testing::cli_path() + " bench --sizes 3000 --methods swap cvdt --max-iterations 2", &out),
      0)
      << out;
  for (const char* row : {"Gmsh mesh (no optimizer) = Init", "Gmsh mesh + Mesh.Optimize",
                          "TetGen -q -O on Init", "swap on Init", "cvdt on Init"})
    EXPECT_NE(out.find(row), std::string::npos) << row;
  EXPECT_EQ(out.find("failed"), std::string::npos) << out;
}

// A 2D mesh through `cvtmesh perturb` and `cvtmesh optimize --hops`: the basin-hopping trials
// show in the progress and the boundary is kept.
TEST(OptimizeCli, TwoDimensionalCvtWithBasinHopping) {
  const std::string dir = testing::temp_dir();
  const std::string pert = dir + "/washer_pert.msh", out = dir + "/washer_cvt.msh";
  std::string log;
  ASSERT_EQ(testing::run(testing::cli_path() + " perturb " + testing::geo_path("washer.geo") +
                             " --set h0=0.16 --set g=0.16 --cluster -o " + pert,
                         &log),
            0)
      << log;
  ASSERT_EQ(testing::run(testing::cli_path() + " optimize " + pert + " -o " + out +
                             " --method cvdt --max-iterations 300 --tolerance 1e-7 --hops 2 "
                             "--hop-amount 0.3 --seed 3 --lbfgs 5 --sizing uniform --allow-worse",
                         &log),
            0)
      << log;
  EXPECT_NE(log.find("hop 2"), std::string::npos) << log;
  const MeshData a = read_mesh(pert), b = read_mesh(out);
  ASSERT_EQ(a.dim, 2);
  ASSERT_EQ(b.dim, 2);
  EXPECT_NO_THROW(verify_optimized(a.tri, b.tri));
  EXPECT_GT(quality_stats(b.tri, "").q_min, quality_stats(a.tri, "").q_min);
  EXPECT_NE(
      testing::run(
          testing::cli_path() + " optimize " + pert + " -o " + dir + "/y.msh --hop-amount 5", &log),
      0);
}

}  // namespace
}  // namespace cvtmesh
