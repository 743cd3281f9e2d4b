// A write that fails midway (full disk, file too large) is simulated with the file size limit
// (RLIMIT_FSIZE through bash's `ulimit -f`, SIGXFSZ ignored so that write() fails with EFBIG
// instead of killing the process): every writer, ours or Gmsh's or OpenMesh's, must end in one
// clear line naming the output, a non-zero exit, no output and no temporary file, and an
// existing output file left as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::vector<std::string> listing(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A directory holding in.msh, a mesh whose output in any format is larger than the limit.
constexpr int kLimitKb = 16;
std::string dir_with_input() {
  const std::string dir = testing::temp_dir();
  std::string log;
  EXPECT_EQ(testing::run(testing::cli_path() + " convert '" + testing::geo_path("cube_sphere.geo") +
                             "' '" + dir + "/in.msh' --set h=0.2 --set h_ball=0.12",
                         &log),
            0)
      << log;
  EXPECT_GT(fs::file_size(dir + "/in.msh"), 3u * 1024 * kLimitKb);
  return dir;
}

// Runs `cvtmesh args` in dir under the file size limit; returns the exit code, *log the output.
int run_limited(const std::string& dir, const std::string& args, std::string* log) {
  return testing::run("cd '" + dir + "' && bash -c \"trap '' XFSZ; ulimit -f " +
                          std::to_string(kLimitKb) + "; exec " + testing::cli_path() + " " + args +
                          "\"",
                      log);
}

void expect_clean_failure(int rc, const std::string& log, const std::string& output) {
  EXPECT_GT(rc, 0) << log;
  EXPECT_LT(rc, 128) << "crashed: " << log;
  std::string line = log;
  while (!line.empty() && line.back() == '\n') line.pop_back();
  EXPECT_EQ(line.find('\n'), std::string::npos) << "more than one line:\n" << log;
  EXPECT_NE(line.find("cannot write '" + output + "'"), std::string::npos) << line;
  EXPECT_EQ(line.find("cvtmesh-tmp"), std::string::npos) << "names the temporary: " << line;
}

TEST(WriteFailure, EveryWriterFailsCleanlyWhenTheFileSizeLimitIsReached) {
  const std::string dir = dir_with_input();
  const std::vector<std::string> before = listing(dir);
  // .msh ASCII and binary (Gmsh), .vtk/.vtu/.mesh/.node (ours), .stl/.off/.ply (OpenMesh).
  for (const std::string out : {"out.msh", "out.msh --binary", "out.vtk", "out.vtu", "out.mesh",
                                "out.node", "out.stl", "out.off", "out.ply"}) {
    SCOPED_TRACE(out);
    const std::string file = out.substr(0, out.find(' '));
    std::string log;
    const int rc = run_limited(dir, "convert in.msh " + out, &log);
    expect_clean_failure(rc, log, file);
    EXPECT_EQ(listing(dir), before) << "an output or temporary file was left";
    // Without the limit the same command succeeds: the limit is what made it fail.
    ASSERT_EQ(
        testing::run("cd '" + dir + "' && " + testing::cli_path() + " convert in.msh " + out, &log),
        0)
        << log;
    EXPECT_GT(fs::file_size(dir + "/" + file), 1024u * kLimitKb);
    for (const auto& e : fs::directory_iterator(dir))
      if (std::find(before.begin(), before.end(), e.path().filename().string()) == before.end())
        fs::remove(e.path());
  }
}

TEST(WriteFailure, AnExistingOutputIsLeftUntouched) {
  const std::string dir = dir_with_input();
  const std::string old = "not a mesh, but the user's file\n";
  std::ofstream(dir + "/out.msh", std::ios::binary) << old;
  const std::vector<std::string> before = listing(dir);
  for (const std::string cmd : {"convert in.msh out.msh", "optimize in.msh -o out.msh -q"}) {
    SCOPED_TRACE(cmd);
    std::string log;
    const int rc = run_limited(dir, cmd, &log);
    expect_clean_failure(rc, log, "out.msh");
    EXPECT_EQ(slurp(dir + "/out.msh"), old);
    EXPECT_EQ(listing(dir), before);
  }
}

}  // namespace
}  // namespace cvtmesh
