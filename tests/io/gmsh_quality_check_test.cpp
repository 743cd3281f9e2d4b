// Our Measure::kGmshIcn against Gmsh's own Plugin(AnalyseMeshQuality), element by element.
#include "core/io/gmsh_quality_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/io/read_mesh.h"
#include "core/quality/quality.h"
#include "core/quality/quality_stats.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

std::string fmt_sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", v);
  return buf;
}

// Largest relative difference |a-b| / max(|b|, 1e-3) and where it occurs.
double max_rel_diff(const std::vector<double>& ours, const std::vector<double>& gmsh) {
  double worst = 0;
  for (std::size_t i = 0; i < ours.size(); ++i)
    worst = std::max(worst, std::fabs(ours[i] - gmsh[i]) / std::max(std::fabs(gmsh[i]), 1e-3));
  return worst;
}

TEST(GmshIcnCheck, MatchesOurIcnOnCubeSphere) {
  const MeshData d = read_mesh(testing::geo_path("cube_sphere.geo"));
  ASSERT_EQ(d.dim, 3);
  const std::vector<double> gmsh = gmsh_icn_per_element(d);
  const std::vector<double> ours = element_qualities(d.tet, Measure::kGmshIcn);
  ASSERT_EQ(gmsh.size(), ours.size());
  ASSERT_EQ(static_cast<int>(ours.size()), d.tet.nb_tets());
  const double diff = max_rel_diff(ours, gmsh);
  RecordProperty("max_rel_diff", fmt_sci(diff));
  EXPECT_LT(diff, 1e-6);
  // Valid tets: ICN in (0, 1].
  for (double v : gmsh) {
    EXPECT_GT(v, 0);
    EXPECT_LE(v, 1 + 1e-12);
  }
  // The measure is not degenerate: the worst and the best tets differ widely.
  const auto [lo, hi] = std::minmax_element(gmsh.begin(), gmsh.end());
  EXPECT_LT(*lo, 0.5);
  EXPECT_GT(*hi, 0.9);
}

TEST(GmshIcnCheck, MatchesOurIcnOnHandMadeTets) {
  // Stretched and sheared copies of the Kuhn cube: very different shapes, all positive.
  for (const double sx : {1.0, 3.0, 0.05}) {
    MeshData d;
    d.dim = 3;
    d.tet = testing::cube6();
    for (int v = 0; v < d.tet.nb_vertices(); ++v) {
      double* p = d.tet.point(v);
      p[0] = sx * p[0] + 0.7 * p[2];
      p[1] = p[1] + 0.2 * p[0];
    }
    const std::vector<double> gmsh = gmsh_icn_per_element(d);
    const std::vector<double> ours = element_qualities(d.tet, Measure::kGmshIcn);
    ASSERT_EQ(gmsh.size(), 6u);
    EXPECT_LT(max_rel_diff(ours, gmsh), 1e-6) << "stretch " << sx;
  }
}

TEST(GmshIcnCheck, MatchesOurIcnOn2DMesh) {
  const std::string dir = testing::temp_dir();
  const std::string geo = dir + "/plate.geo";
  std::ofstream(geo) << "SetFactory(\"OpenCASCADE\");\n"
                        "Rectangle(1) = {0, 0, 0, 2, 1};\n"
                        "Disk(2) = {0.6, 0.5, 0, 0.25};\n"
                        "BooleanDifference(3) = {Surface{1}; Delete;}{Surface{2}; Delete;};\n"
                        "Mesh.MeshSizeMax = 0.08;\n";
  const MeshData d = read_mesh(geo);
  ASSERT_EQ(d.dim, 2);
  const std::vector<double> gmsh = gmsh_icn_per_element(d);
  const std::vector<double> ours = element_qualities(d.tri, Measure::kGmshIcn);
  ASSERT_EQ(gmsh.size(), ours.size());
  ASSERT_GT(ours.size(), 100u);
  const double diff = max_rel_diff(ours, gmsh);
  RecordProperty("max_rel_diff", fmt_sci(diff));
  EXPECT_LT(diff, 1e-6);
}

}  // namespace
}  // namespace cvtmesh
