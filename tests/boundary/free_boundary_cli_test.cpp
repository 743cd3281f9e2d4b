// End to end: the default method moves the boundary within its bounds (Hausdorff, volume, on the
// entities: the run's own invariant checks), including a two-region interface; --fix-boundary
// keeps every boundary node where it was and, where the pre-issue-13 binary is available
// (CVTMESH_BASELINE_CLI), gives byte-identical output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>

#include "core/io/read_mesh.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Meshes cube_sphere (coarse) into dir/in.msh.
std::string coarse_cube_sphere(const std::string& dir, const std::string& extra = "") {
  std::string log;
  const std::string in = dir + "/in.msh";
  EXPECT_EQ(testing::run(testing::cli_path() + " mesh '" + testing::geo_path("cube_sphere.geo") +
                             "' --set h=0.16 --set h_ball=0.1 " + extra + " -o '" + in + "'",
                         &log),
            0)
      << log;
  return in;
}

// Boundary nodes (class dim < 3) of a mesh file, by node tag.
std::map<std::size_t, std::array<double, 3>> boundary_nodes(const std::string& path) {
  const MeshData d = read_mesh(path, {});
  std::map<std::size_t, std::array<double, 3>> out;
  for (int v = 0; v < d.tet.nb_vertices(); ++v)
    if (d.tet.vclass[v].dim < 3)
      out[d.tet.node_tags[v]] = {d.tet.point(v)[0], d.tet.point(v)[1], d.tet.point(v)[2]};
  return out;
}

TEST(FreeBoundaryCli, DefaultMethodMovesTheBoundaryWithinItsBounds) {
  const std::string dir = testing::temp_dir();
  const std::string in = coarse_cube_sphere(dir);
  std::string log;
  ASSERT_EQ(
      testing::run(
          testing::cli_path() + " optimize '" + in + "' --binary -o '" + dir + "/free.msh'", &log),
      0)
      << log;
  std::smatch mt;
  ASSERT_TRUE(std::regex_search(
      log, mt,
      std::regex("free boundary: .*; ([0-9]+) vertices moved, Hausdorff ([0-9.e+-]+) .*bound "
                 "([0-9.e+-]+)\\), volume change ([0-9.e+-]+) %")))
      << log;
  EXPECT_GT(std::stoi(mt[1]), 0);
  EXPECT_LE(std::stod(mt[2]), std::stod(mt[3]));
  EXPECT_LE(std::stod(mt[4]), 0.5);
  // Some boundary node moved; the surface coarsening removed some (never adds one): the others
  // keep their tags.
  std::size_t removed = 0;
  if (std::regex_search(log, mt,
                        std::regex("surface coarsening: ([0-9]+) surface vertices removed")))
    removed = std::stoul(mt[1]);
  const auto a = boundary_nodes(in), b = boundary_nodes(dir + "/free.msh");
  ASSERT_EQ(a.size(), b.size() + removed);
  int moved = 0;
  for (const auto& [tag, p] : b) {
    ASSERT_TRUE(a.count(tag)) << "boundary node " << tag << " is new";
    moved += a.at(tag) != p;
  }
  EXPECT_GT(moved, 0);
}

TEST(FreeBoundaryCli, TwoRegionInterfaceMovesAsOneSurface) {
  const std::string dir = testing::temp_dir();
  const std::string in = coarse_cube_sphere(dir, "--set two_regions=1");
  std::string log;
  // The run's invariants (same interface triangles on both sides, group boundaries, volumes of
  // both regions within bounds) throw on failure: exit code 0 means they held.
  ASSERT_EQ(
      testing::run(testing::cli_path() + " optimize '" + in + "' -o '" + dir + "/two.msh'", &log),
      0)
      << log;
  const MeshData d = read_mesh(dir + "/two.msh", {});
  const MeshData d0 = read_mesh(in, {});
  // Interface (ball surface) nodes moved and stayed on the ball (radius 0.25 within 2e-3 relative).
  int moved = 0;
  std::map<std::size_t, int> index;
  for (int v = 0; v < d0.tet.nb_vertices(); ++v) index[d0.tet.node_tags[v]] = v;
  for (int v = 0; v < d.tet.nb_vertices(); ++v) {
    if (d.tet.vclass[v].dim != 2) continue;
    const double* p = d.tet.point(v);
    const double r = std::sqrt((p[0] - .5) * (p[0] - .5) + (p[1] - .5) * (p[1] - .5) +
                               (p[2] - .5) * (p[2] - .5));
    if (std::fabs(r - 0.25) > 0.05) continue;  // a cube face node
    const double* p0 = d0.tet.point(index.at(d.tet.node_tags[v]));
    if (p[0] != p0[0] || p[1] != p0[1] || p[2] != p0[2]) ++moved;
    EXPECT_NEAR(r, 0.25, 0.25 * 2e-2);
  }
  EXPECT_GT(moved, 0);
}

// A CAD model the CLI meshes itself: the free boundary moves on the CAD (the report says so), and
// every surface and curve node of the output lies on the exact sphere to 1e-12.
TEST(FreeBoundaryCli, GeoInputMovesOnTheCadSphereTo1e12) {
  const std::string dir = testing::temp_dir();
  const std::string geo = dir + "/ball.geo";
  {
    std::ofstream f(geo);
    f << "SetFactory(\"OpenCASCADE\");\nSphere(1) = {0.1, 0.2, 0.3, 1};\n"
         "Mesh.MeshSizeMax = 0.3;\nMesh.MeshSizeMin = 0.3;\n";
  }
  std::string log;
  ASSERT_EQ(
      testing::run(testing::cli_path() + " optimize '" + geo + "' -o '" + dir + "/b.msh'", &log), 0)
      << log;
  EXPECT_NE(log.find("free boundary: cad geometry"), std::string::npos) << log;
  std::smatch mt;
  ASSERT_TRUE(std::regex_search(log, mt, std::regex("; ([0-9]+) vertices moved"))) << log;
  EXPECT_GT(std::stoi(mt[1]), 0) << log;
  const MeshData d = read_mesh(dir + "/b.msh", {});
  int on_boundary = 0;
  for (int v = 0; v < d.tet.nb_vertices(); ++v) {
    if (d.tet.vclass[v].dim == 3) continue;
    const double* p = d.tet.point(v);
    const double r = std::sqrt((p[0] - .1) * (p[0] - .1) + (p[1] - .2) * (p[1] - .2) +
                               (p[2] - .3) * (p[2] - .3));
    EXPECT_LE(std::fabs(r - 1), 1e-12) << "node " << d.tet.node_tags[v];
    ++on_boundary;
  }
  EXPECT_GT(on_boundary, 50);
}

TEST(FreeBoundaryCli, FixBoundaryKeepsEveryBoundaryNodeAndMatchesTheBaseline) {
  const std::string dir = testing::temp_dir();
  const std::string in = coarse_cube_sphere(dir);
  std::string log;
  ASSERT_EQ(testing::run(testing::cli_path() + " optimize '" + in +
                             "' --fix-boundary --binary -q -o '" + dir + "/fixed.msh'",
                         &log),
            0)
      << log;
  EXPECT_EQ(boundary_nodes(in), boundary_nodes(dir + "/fixed.msh"));
  const char* baseline = std::getenv("CVTMESH_BASELINE_CLI");
  if (!baseline || !std::filesystem::exists(baseline))
    GTEST_SKIP() << "set CVTMESH_BASELINE_CLI to the pre-issue-13 cvtmesh for the byte comparison";
  ASSERT_EQ(testing::run(std::string(baseline) + " optimize '" + in + "' --binary -q -o '" + dir +
                             "/baseline.msh'",
                         &log),
            0)
      << log;
  EXPECT_TRUE(slurp(dir + "/fixed.msh") == slurp(dir + "/baseline.msh"));
}

}  // namespace
}  // namespace cvtmesh
