// End-to-end: perturb -> optimize_2d (cvdt, dl, wdl) on the paper's two examples, fixed seeds.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "core/pipeline/option_schema.h"
#include "core/io/read_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/optimize2d.h"
#include "core/pipeline/perturb2d.h"
#include "core/quality/quality_stats.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

using testing::max_nearest_distance;

void expect_boundary_kept(const TriMesh2& before, const TriMesh2& after) {
  ASSERT_EQ(before.nb_vertices(), after.nb_vertices());
  EXPECT_EQ(before.edges, after.edges);
  for (int v = 0; v < before.nb_vertices(); ++v)
    if (before.vclass[v].dim != 2) {
      EXPECT_EQ(before.point(v)[0], after.point(v)[0]);
      EXPECT_EQ(before.point(v)[1], after.point(v)[1]);
    }
}

// The quad from both perturbations: every method improves the perturbed mesh; CVT returns to
// the regular mesh from both (so both CVT results coincide).
TEST(Optimize2d, QuadFromBothPerturbations) {
  const int n = 8;
  const MeshData d =
      read_mesh(testing::geo_path("quad.geo"), {.dim = 2, .set_numbers = {{"n", double(n)}}});
  for (Perturbation2d kind : {Perturbation2d::kRandom, Perturbation2d::kCluster}) {
    SCOPED_TRACE(kind == Perturbation2d::kRandom ? "RandPert" : "ClusPert");
    TriMesh2 pert = d.tri;
    perturb_2d(pert, {.kind = kind, .seed = 2});
    for (const std::string method : {"cvdt", "dl", "wdl"}) {
      SCOPED_TRACE(method);
      TriMesh2 m = pert;
      OptimizeOptions o;
      o.method = method;
      o.sizing = "uniform";
      o.max_iterations = 1000;
      o.tolerance = 1e-12;
      int calls = 0;
      o.progress = [&](const OptimizeProgress& p) {
        if (p.start) return;  // a phase begins (the final checks): not an iteration
        ++calls;
        EXPECT_EQ(p.phase, method == "cvdt" ? "lloyd" : method);
      };
      const OptimizeResult r = optimize_2d(m, o);
      EXPECT_TRUE(check_mesh(m).ok);
      expect_boundary_kept(pert, m);
      EXPECT_EQ(calls, r.iterations);
      EXPECT_EQ(r.after.nb_inverted, 0);
      EXPECT_GT(r.after.q_avg, r.before.q_avg);
      EXPECT_GT(r.after.q_min, r.before.q_min);
      if (method == "cvdt") {
        EXPECT_TRUE(r.converged);
        EXPECT_LT(max_nearest_distance(m, d.tri), 1e-3 / n);
        EXPECT_GE(r.after.q_avg, 0.995);
      }
    }
  }
}

// The washer (coarse version of washer.geo) from both perturbations: CVT with the analytic
// sizing is valid, keeps the boundary, improves the minimum quality strongly, and the two CVT
// results are of the same quality (the paper's insensitivity to the initial distribution).
TEST(Optimize2d, WasherCvtFromBothPerturbations) {
  const double h0 = 0.16, g = 0.16;
  const MeshData d =
      read_mesh(testing::geo_path("washer.geo"), {.dim = 2, .set_numbers = {{"h0", h0}, {"g", g}}});
  double q_avg[2];
  int k = 0;
  for (Perturbation2d kind : {Perturbation2d::kRandom, Perturbation2d::kCluster}) {
    SCOPED_TRACE(kind == Perturbation2d::kRandom ? "RandPert" : "ClusPert");
    TriMesh2 m = d.tri;
    perturb_2d(m, {.kind = kind, .seed = 2});
    const TriMesh2 pert = m;
    OptimizeOptions o;
    o.method = "cvdt";
    o.sizing = "function";
    o.size_function = [&](const double* x) { return h0 + g * (std::hypot(x[0], x[1]) - 1.0); };
    o.max_iterations = 400;
    o.tolerance = 1e-9;
    const OptimizeResult r = optimize_2d(m, o);
    EXPECT_TRUE(check_mesh(m).ok);
    expect_boundary_kept(pert, m);
    EXPECT_GT(r.after.q_min, r.before.q_min + 0.3);
    EXPECT_GT(r.after.min_angle, 30.0);
    q_avg[k++] = r.after.q_avg;
  }
  EXPECT_NEAR(q_avg[0], q_avg[1], 0.01);
}

// Two surfaces sharing an interface (a rectangle split at x = 1), default "mesh" sizing: every
// method keeps the interface, both surfaces and their areas (verify_optimized runs inside), and
// no vertex crosses into the other surface.
TEST(Optimize2d, TwoSurfacesKeepTheirInterface) {
  const std::string dir = testing::temp_dir();
  const std::string geo = dir + "/two.geo";
  {
    std::ofstream f(geo);
    f << "h = 0.1;\n"
         "Point(1) = {0, 0, 0, h}; Point(2) = {1, 0, 0, h}; Point(3) = {2, 0, 0, h};\n"
         "Point(4) = {2, 1, 0, h}; Point(5) = {1, 1, 0, h}; Point(6) = {0, 1, 0, h};\n"
         "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};\n"
         "Line(5) = {5, 6}; Line(6) = {6, 1}; Line(7) = {2, 5};\n"
         "Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1};\n"
         "Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};\n";
  }
  const MeshData d = read_mesh(geo, {.dim = 2});
  ASSERT_EQ(d.dim, 2);
  TriMesh2 pert = d.tri;
  perturb_2d(pert, {.kind = Perturbation2d::kRandom, .seed = 9, .amount = 0.45});
  ASSERT_TRUE(check_mesh(pert).ok);
  for (const std::string method : {"cvdt", "dl", "wdl"}) {
    SCOPED_TRACE(method);
    TriMesh2 m = pert;
    OptimizeOptions o;
    o.method = method;
    o.max_iterations = 200;
    const OptimizeResult r = optimize_2d(m, o);  // verify = true: throws on a broken invariant
    EXPECT_GT(r.after.q_min, r.before.q_min);
    for (int t = 0; t < m.nb_tris(); ++t)
      for (int k = 0; k < 3; ++k) {
        const double x = m.point(m.tris[3 * t + k])[0];
        if (m.tri_region[t] == 1)
          EXPECT_LE(x, 1.0);
        else
          EXPECT_GE(x, 1.0);
      }
  }
  std::filesystem::remove_all(dir);
}

TEST(Optimize2d, RejectsA3dMethod) {
  TriMesh2 m = testing::square2();
  OptimizeOptions o;
  o.method = "combined";
  EXPECT_THROW(optimize_2d(m, o), OptionError);
}

// cvdt with basin hopping: the progress goes through "lloyd", then "hop 1", "hop 2" in order,
// and the result passes the invariant checks (verify) and keeps the boundary.
TEST(Optimize2d, WasherCvtWithBasinHopping) {
  const double h0 = 0.16, g = 0.16;
  const MeshData d =
      read_mesh(testing::geo_path("washer.geo"), {.dim = 2, .set_numbers = {{"h0", h0}, {"g", g}}});
  TriMesh2 m = d.tri;
  perturb_2d(m, {.kind = Perturbation2d::kRandom, .seed = 2});
  const TriMesh2 pert = m;
  OptimizeOptions o;
  o.method = "cvdt";
  o.sizing = "function";
  o.size_function = [&](const double* x) { return h0 + g * (std::hypot(x[0], x[1]) - 1.0); };
  o.max_iterations = 1000;
  o.tolerance = 1e-8;
  o.hops = 2;
  o.seed = 5;
  std::vector<std::string> phases;
  o.progress = [&](const OptimizeProgress& p) {
    if (p.start) return;  // a phase begins (the final checks): not an iteration
    if (phases.empty() || phases.back() != p.phase) phases.push_back(p.phase);
  };
  const OptimizeResult r = optimize_2d(m, o);
  EXPECT_EQ(phases, (std::vector<std::string>{"lloyd", "hop 1", "hop 2"}));
  EXPECT_TRUE(check_mesh(m).ok);
  expect_boundary_kept(pert, m);
  EXPECT_EQ(r.after.nb_inverted, 0);
  EXPECT_GT(r.after.q_min, r.before.q_min + 0.3);
}

}  // namespace
}  // namespace cvtmesh
