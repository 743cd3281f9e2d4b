// TetGen runs in a child process (core/delaunay/tetrahedralize_isolated.h): the rebuild gives the
// same mesh as in process, a child that dies by a signal becomes an InvariantError naming the
// stage and the signal (this process lives on), and a TetGen error code one naming the error.
#include "core/delaunay/tetrahedralize_isolated.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <string>

#include "core/delaunay/delaunay3.h"
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

TEST(TetrahedralizeIsolated, ChildGivesTheSameMeshAsInProcess) {
  const TetMesh input = testing::delaunay_of_points(testing::cube_lattice(3, 0.2));
  TetMesh child = input, in_process = input;
  Delaunay3::create("tetgen")->retetrahedralize(child);
  {
    ScopedEnv env("CVTMESH_TETGEN_IN_PROCESS", "1");
    Delaunay3::create("tetgen")->retetrahedralize(in_process);
  }
  EXPECT_TRUE(check_mesh(child).ok);
  EXPECT_EQ(child.tets, in_process.tets);
  EXPECT_EQ(child.xyz, in_process.xyz);
  EXPECT_EQ(child.tet_region, in_process.tet_region);
}

TEST(TetrahedralizeIsolated, ChildDyingBySignalIsAnInvariantErrorNamingTheStage) {
  TetMesh m = testing::delaunay_of_points(testing::cube_lattice(2));
  const TetMesh before = m;
  ScopedEnv env("CVTMESH_TETGEN_CHILD_SIGNAL", "9");  // SIGKILL: no handler (ASan) catches it
  try {
    Delaunay3::create("tetgen")->retetrahedralize(m);
    ADD_FAILURE() << "no error";
  } catch (const InvariantError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("signal 9"), std::string::npos) << what;
    EXPECT_NE(what.find("rebuild"), std::string::npos) << what;
  }
  EXPECT_EQ(m.tets, before.tets);  // the mesh is left as it was
}

}  // namespace
}  // namespace cvtmesh
