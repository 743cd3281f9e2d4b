// The 3D methods through optimize(): every region of a multi-region model, interfaces and
// physical groups kept, the invariants verified at the end of each run.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <tuple>

#include "core/pipeline/option_schema.h"
#include "core/io/read_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/optimize.h"
#include "core/pipeline/verify_mesh.h"
#include "core/quality/quality_stats.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

MeshData two_region_cube_sphere() {
  return testing::cube_sphere(0.14, 0.1, false, {{"two_regions", 1}});
}

TEST(Optimize3d, EveryMethodKeepsRegionsInterfacesAndGroupsOfTheTwoRegionModel) {
  const MeshData init = two_region_cube_sphere();
  ASSERT_EQ(region_volumes(init.tet).size(), 2u);
  for (const char* method :
       {"cvdt", "cvdt+swap", "cvdt+swap+smooth", "combined", "swap", "smooth"}) {
    MeshData d = init;
    OptimizeOptions o;
    o.method = method;
    o.max_iterations = 6;
    o.fix_boundary = true;  // the free boundary: tests/boundary/
    o.never_worse = false;  // each method itself, not the fallback (tests/robust/)
    const OptimizeResult r = optimize(d, o);  // runs verify_optimized (throws on a violation)
    EXPECT_EQ(r.method, method);
    EXPECT_TRUE(check_mesh(d.tet).ok) << method;
    EXPECT_NO_THROW(verify_optimized(init.tet, d.tet)) << method;
    const auto va = region_volumes(d.tet), vb = region_volumes(init.tet);
    ASSERT_EQ(va.size(), 2u);
    for (int i = 0; i < 2; ++i)
      EXPECT_NEAR(va[i].second, vb[i].second, 1e-12 * vb[i].second) << method;
    EXPECT_EQ(d.tet.model.groups.size(), init.tet.model.groups.size());
    // Quality rises on average for every method on this unoptimized input.
    EXPECT_GT(r.after.q_avg, r.before.q_avg) << method;
    EXPECT_GE(r.after.q_min, method == std::string("cvdt") ? -1.0 : r.before.q_min) << method;
  }
}

TEST(Optimize3d, UnknownMethodAndWrongDimensionAreRefused) {
  MeshData d = two_region_cube_sphere();
  OptimizeOptions o;
  o.method = "dl";  // a 2D method
  EXPECT_THROW(optimize(d, o), OptionError);
  o.method = "nonsense";
  EXPECT_THROW(optimize(d, o), OptionError);
  const auto m3 = methods_for_dim(3);
  EXPECT_EQ(m3.front(), "cvdt+swap+smooth");
  EXPECT_NE(std::find(m3.begin(), m3.end(), "combined"), m3.end());
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

TEST(Optimize3d, LloydMethodsReportNotConvergedWhenStoppedByTheIterationLimit) {
  const MeshData init = two_region_cube_sphere();
  for (const char* method : {"cvdt", "cvdt+swap", "cvdt+swap+smooth"}) {
    MeshData d = init;
    OptimizeOptions o;
    o.method = method;
    o.max_iterations = 2;
    o.tolerance = 0;  // cannot be reached
    const OptimizeResult r = optimize(d, o);
    EXPECT_EQ(r.iterations, 2) << method;
    EXPECT_FALSE(r.converged) << method;
    // One time per Lloyd iteration (the bench's median column), within the phases' time.
    ASSERT_EQ(r.lloyd_iteration_seconds.size(), r.lloyd_energy.size()) << method;
    ASSERT_GE(r.lloyd_iteration_seconds.size(), 2u) << method;
    double sum = 0;
    for (double s : r.lloyd_iteration_seconds) {
      EXPECT_GT(s, 0) << method;
      sum += s;
    }
    EXPECT_LE(sum, r.seconds_lloyd) << method;
  }
}

}  // namespace
}  // namespace cvtmesh

#include <omp.h>

#include "core/util/thread_count.h"
#include "tests/support/thread_counts.h"

namespace cvtmesh {
namespace {

// Gmsh sets the process's OpenMP thread count to its General.NumThreads (1 here) whenever a mesh
// is read: optimize must run its loops on our count (default_thread_count) anyway, and give the
// caller's count back afterwards.
TEST(Optimize3d, RunsOnItsOwnThreadCountAndRestoresTheCallers) {
  const MeshData init = testing::cube_sphere(0.2, 0.15);  // read through Gmsh
  testing::ThreadCountGuard restore;
  omp_set_num_threads(1);
  MeshData d = init;
  OptimizeOptions o;
  o.method = "cvdt";
  o.max_iterations = 2;
  std::vector<int> seen;
  o.progress = [&](const OptimizeProgress&) { seen.push_back(omp_get_max_threads()); };
  optimize(d, o);
  const int after = omp_get_max_threads();
  ASSERT_FALSE(seen.empty());
  for (int n : seen) EXPECT_EQ(n, default_thread_count());
  EXPECT_EQ(after, 1);
  EXPECT_GE(default_thread_count(), 1);
}

}  // namespace
}  // namespace cvtmesh
