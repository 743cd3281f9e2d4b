// Whole-CLI determinism: the same input, options and seed give byte-identical output files, run
// after run and for any number of OpenMP threads (OMP_NUM_THREADS=1 vs 2). Binary .msh output, so
// every bit of every coordinate is compared.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Runs `args` (a cvtmesh command line writing `out` in dir) with the given thread count; returns
// the bytes of `out`.
std::string run_with_threads(int threads, const std::string& dir, const std::string& args,
                             const std::string& out) {
  std::filesystem::remove(dir + "/" + out);  // no stale output from an earlier run
  std::string log;
  const int rc = testing::run("cd '" + dir + "' && OMP_NUM_THREADS=" + std::to_string(threads) +
                                  " " + testing::cli_path() + " " + args,
                              &log);
  EXPECT_EQ(rc, 0) << args << "\n" << log;
  return slurp(dir + "/" + out);
}

// The three runs: 2 threads twice, then 1 thread; all outputs identical and non-trivial.
void expect_deterministic(const std::string& dir, const std::string& args, const std::string& out) {
  const std::string a = run_with_threads(2, dir, args, out);
  const std::string b = run_with_threads(2, dir, args, out);
  const std::string c = run_with_threads(1, dir, args, out);
  ASSERT_GT(a.size(), 1000u) << args;
  EXPECT_TRUE(a == b) << "two runs of '" << args << "' differ";
  EXPECT_TRUE(a == c) << "'" << args << "' differs between 1 and 2 threads";
}

TEST(Determinism, Optimize3dDefaultMethodBinaryMsh) {
  const std::string dir = testing::temp_dir();
  // A .geo meshed by Gmsh inside each run, then cvdt+swap+smooth (the default method).
  expect_deterministic(dir,
                       "optimize '" + testing::geo_path("cube_sphere.geo") +
                           "' --set h=0.2 --set h_ball=0.12 --max-iterations 5 --binary -q "
                           "-o out3d.msh",
                       "out3d.msh");
}

// A mesh large enough (~6.5k tets) that the parallel per-tet loops of the default method run on
// two threads (the scans of the max-min smoothings, the swaps' qualities, the time-step guard's
// nodal sums, each written per tet and reduced in tet order; the Laplacian's colours stay on one
// thread below 2048 vertices).
TEST(Determinism, Optimize3dDefaultMethodParallelStagesBinaryMsh) {
  const std::string dir = testing::temp_dir();
  expect_deterministic(dir,
                       "optimize '" + testing::geo_path("cube_sphere.geo") +
                           "' --set h=0.1 --set h_ball=0.08 --binary -q -o out3d_par.msh",
                       "out3d_par.msh");
}

TEST(Determinism, Perturb2dThenOptimize2dBinaryMsh) {
  const std::string dir = testing::temp_dir();
  const std::string geo = testing::geo_path("washer.geo");
  expect_deterministic(
      dir,
      "perturb '" + geo + "' --set h0=0.16 --set g=0.16 --random --seed 7 --binary -o pert.msh",
      "pert.msh");
  // The comparison sees a change: another seed gives another file.
  const std::string seed7 = slurp(dir + "/pert.msh");
  EXPECT_FALSE(run_with_threads(2, dir,
                                "perturb '" + geo +
                                    "' --set h0=0.16 --set g=0.16 --random --seed 8 --binary -o "
                                    "pert8.msh",
                                "pert8.msh") == seed7);
  // The perturbed mesh (the same bytes in every run above) optimized by the 2D default method.
  expect_deterministic(dir, "optimize pert.msh --max-iterations 8 --binary -q -o opt2d.msh",
                       "opt2d.msh");
}

// The programs start themselves again with OMP_WAIT_POLICY=passive when neither it nor
// GOMP_SPINCOUNT is set (core/util/wait_policy.h): that path (both unset) and a run that keeps
// its spinning threads (active) give the same bytes, and the arguments reach the new image.
TEST(Determinism, SameFileWhetherTheProgramRestartsWithPassiveThreads) {
  const std::string dir = testing::temp_dir();
  const std::string args = "optimize '" + testing::geo_path("cube_sphere.geo") +
                           "' --set h=0.2 --set h_ball=0.12 --max-iterations 5 --binary -q "
                           "-o w.msh";
  auto run = [&](const std::string& env) {
    std::filesystem::remove(dir + "/w.msh");
    std::string log;
    const int rc = testing::run(
        "cd '" + dir + "' && env " + env + " " + testing::cli_path() + " " + args, &log);
    EXPECT_EQ(rc, 0) << env << "\n" << log;
    return slurp(dir + "/w.msh");
  };
  const std::string restarted = run("-u OMP_WAIT_POLICY -u GOMP_SPINCOUNT");
  const std::string spinning = run("-u GOMP_SPINCOUNT OMP_WAIT_POLICY=active");
  ASSERT_GT(restarted.size(), 1000u);
  EXPECT_TRUE(restarted == spinning);
}

}  // namespace
}  // namespace cvtmesh
