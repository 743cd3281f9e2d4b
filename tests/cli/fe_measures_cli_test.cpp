// End-to-end: the FE measures in `cvtmesh stats` (issue 16): the JSON keys, --wave-speed,
// --fe-measures off, and a bad value refused.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

using testing::run;

nlohmann::json stats_json(const std::string& args) {
  std::string out;
  const int rc = run(testing::cli_path() + " stats '" + testing::geo_path("cube_sphere.geo") +
                         "' --set h=0.2 --set h_ball=0.15 --format json " + args + " 2>/dev/null",
                     &out);
  EXPECT_EQ(rc, 0) << out;
  return nlohmann::json::parse(out);  // one mesh: one object (docs/cli.md, JSON)
}

TEST(FeMeasuresCli, StatsHasTheKeysAndTheWaveSpeedScalesTheSteps) {
  const auto a = stats_json("");
  for (const char* k : {"time_step", "element_time_step", "cg_iterations", "stiffness_condition"})
    ASSERT_TRUE(a[k].is_number()) << k << " in " << a.dump();
  EXPECT_LE(a["element_time_step"].get<double>(), a["time_step"].get<double>());
  EXPECT_GT(a["cg_iterations"].get<long>(), 0);
  const auto b = stats_json("--wave-speed 4");
  EXPECT_NEAR(b["time_step"].get<double>(), a["time_step"].get<double>() / 4,
              1e-12 * a["time_step"].get<double>());
  EXPECT_EQ(b["cg_iterations"], a["cg_iterations"]);
  const auto off = stats_json("--fe-measures off");
  EXPECT_TRUE(off["time_step"].is_null());
  EXPECT_TRUE(off["cg_iterations"].is_null());
  std::string out;
  EXPECT_NE(run(testing::cli_path() + " stats '" + testing::geo_path("cube_sphere.geo") +
                    "' --wave-speed -1 2>&1",
                &out),
            0);
  EXPECT_NE(out.find("wave-speed"), std::string::npos) << out;
}

}  // namespace
}  // namespace cvtmesh
