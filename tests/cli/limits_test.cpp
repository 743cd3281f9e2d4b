// The service limits of the CLI (convert/limits.h): --time-limit and --max-memory stop the run
// with exit 2 and a message, and leave neither an output nor a temporary file.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

namespace fs = std::filesystem;

int files_in(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) (void)e, ++n;
  return n;
}

TEST(CliLimits, TheTimeLimitStopsTheRunWithoutOutput) {
  const fs::path dir = testing::temp_dir();
  std::string log;
  // The default pipeline on cube_sphere takes well over a second (meshing included).
  const int rc =
      testing::run(testing::cli_path() + " optimize " + testing::geo_path("cube_sphere.geo") +
                       " -o " + (dir / "out.msh").string() + " -q --time-limit 0.2",
                   &log);
  EXPECT_EQ(rc, 2) << log;
  EXPECT_NE(log.find("time limit of 0.2 s reached"), std::string::npos) << log;
  EXPECT_EQ(files_in(dir), 0) << log;
}

TEST(CliLimits, TheMemoryLimitIsAnErrorNotACrash) {
  const fs::path dir = testing::temp_dir();
  std::string log;
  const int rc = testing::run(testing::cli_path() + " --max-memory 60 optimize " +
                                  testing::geo_path("cube_sphere.geo") + " -o " +
                                  (dir / "out.msh").string() + " -q",
                              &log);
  EXPECT_EQ(rc, 2) << log;
  EXPECT_NE(log.find("out of memory"), std::string::npos) << log;
  EXPECT_EQ(files_in(dir), 0) << log;
  // A generous limit changes nothing.
  EXPECT_EQ(testing::run(testing::cli_path() + " stats " + testing::geo_path("quad.geo") +
                             " --max-memory 4000",
                         &log),
            0)
      << log;
}

}  // namespace
}  // namespace cvtmesh
