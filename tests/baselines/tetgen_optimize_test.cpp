// The TetGen -O baseline runs TetGen in a child process (core/delaunay/tetrahedralize_isolated.h):
// same result as in process, and a crash inside TetGen is an InvariantError for compare / bench
// to report as that column's failure, not the end of the process.
#include "bench/baselines/tetgen_optimize.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <string>

#include "core/mesh/check_mesh.h"
#include "core/util/error.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

struct ScopedEnv {
  const char* name;
  ScopedEnv(const char* n, const char* value) : name(n) { setenv(n, value, 1); }
  ~ScopedEnv() { unsetenv(name); }
};

TEST(TetgenOptimizeBaseline, ChildGivesTheSameMeshAsInProcess) {
  const MeshData d = testing::cube_sphere(0.3, 0.15);
  TetMesh child = d.tet, in_process = d.tet;
  tetgen_optimize(child);
  {
    ScopedEnv env("CVTMESH_TETGEN_IN_PROCESS", "1");
    tetgen_optimize(in_process);
  }
  EXPECT_TRUE(check_mesh(child).ok);
  EXPECT_EQ(child.tets, in_process.tets);
  EXPECT_EQ(child.xyz, in_process.xyz);
  EXPECT_EQ(child.tet_region, in_process.tet_region);
}

TEST(TetgenOptimizeBaseline, ACrashInTetgenIsAnInvariantError) {
  const MeshData d = testing::cube_sphere(0.3, 0.15);
  TetMesh m = d.tet;
  ScopedEnv env("CVTMESH_TETGEN_CHILD_SIGNAL", "9");
  try {
    tetgen_optimize(m);
    ADD_FAILURE() << "no error";
  } catch (const InvariantError& e) {
    EXPECT_NE(std::string(e.what()).find("signal 9"), std::string::npos) << e.what();
  }
  EXPECT_EQ(m.tets, d.tet.tets);  // left as it was
}

}  // namespace
}  // namespace cvtmesh
