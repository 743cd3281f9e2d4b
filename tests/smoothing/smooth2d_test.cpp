// DL and WDL (Laplacian / weighted Laplacian smoothing + Delaunay flips) in 2D.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/io/read_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/face_key.h"
#include "core/pipeline/perturb2d.h"
#include "core/quality/quality_stats.h"
#include "core/smoothing/dl_optimize_2d.h"
#include "core/smoothing/wdl_optimize_2d.h"
#include "core/swap/flip2d_delaunay.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

int nb_not_delaunay(const TriMesh2& m) {
  std::set<EdgeKey> cons;
  for (int e = 0; e < m.nb_edges(); ++e) cons.insert(edge_key(m.edges[2 * e], m.edges[2 * e + 1]));
  int bad = 0;
  for (int t = 0; t < m.nb_tris(); ++t)
    for (int e = 0; e < 3; ++e) {
      const int* tv = &m.tris[3 * t];
      if (!cons.count(edge_key(tv[(e + 1) % 3], tv[(e + 2) % 3])) &&
          !is_locally_delaunay2d(m, 3 * t + e))
        ++bad;
    }
  return bad;
}

// A star whose Laplacian target (the mean of its ring, (1.26, -0.01)) lies outside its kernel:
// moving there would invert the triangle (v, B, C), so the move is rejected.
TEST(Smooth2d, MoveThatWouldInvertIsRejected) {
  TriMesh2 m;
  m.xy = {0, 0, -1, -1, 4, -1, 0.3, -0.05, 4, 1, -1, 1};  // v, A, B, C (reflex), D, E
  m.vclass = {VertexClass{2, 1}};
  for (int k = 1; k <= 5; ++k) {
    m.vclass.push_back(VertexClass{1, 1});
    m.tris.insert(m.tris.end(), {0, k, k % 5 + 1});
    m.tri_region.push_back(1);
    m.edges.insert(m.edges.end(), {k, k % 5 + 1});
    m.edge_curve.push_back(1);
  }
  build_adjacency2(m);
  ASSERT_TRUE(check_mesh(m).ok);
  Smooth2dOptions o;
  o.loop.max_iterations = 1;
  o.flips = false;
  o.sizing.kind = "uniform";
  int limited = -1;
  dl_optimize_2d(m, o, [&](const LloydStep& s) { limited = s.nb_limited; });
  EXPECT_EQ(limited, 1);
  EXPECT_EQ(m.point(0)[0], 0.0);
  EXPECT_EQ(m.point(0)[1], 0.0);
  EXPECT_TRUE(check_mesh(m).ok);
}

// DL and WDL on the randomly perturbed quad: valid throughout, boundary fixed, Delaunay at the
// end, converged, and much better than the perturbed mesh.
TEST(Smooth2d, DlAndWdlOnPerturbedQuad) {
  const MeshData d =
      read_mesh(testing::geo_path("quad.geo"), {.dim = 2, .set_numbers = {{"n", 8}}});
  TriMesh2 pert = d.tri;
  perturb_2d(pert, {.kind = Perturbation2d::kRandom, .seed = 5});
  const QualityStats before = quality_stats(pert, "pert");
  for (bool weighted : {false, true}) {
    TriMesh2 m = pert;
    Smooth2dOptions o;
    o.loop.max_iterations = 300;
    o.loop.tolerance = 1e-10;
    o.sizing.kind = "uniform";  // h = the boundary edge length, the regular mesh's
    int invalid = 0;
    const LloydResult r = (weighted ? wdl_optimize_2d : dl_optimize_2d)(
        m, o, [&](const LloydStep&) { invalid += check_mesh(m).ok ? 0 : 1; });
    SCOPED_TRACE(weighted ? "WDL" : "DL");
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(invalid, 0);
    for (int v = 0; v < m.nb_vertices(); ++v)
      if (m.vclass[v].dim != 2) {
        EXPECT_EQ(m.point(v)[0], pert.point(v)[0]);
        EXPECT_EQ(m.point(v)[1], pert.point(v)[1]);
      }
    EXPECT_EQ(nb_not_delaunay(m), 0);
    const QualityStats after = quality_stats(m, "after");
    EXPECT_GT(after.q_min, before.q_min + 0.2);
    EXPECT_GT(after.q_avg, before.q_avg + 0.05);
  }
}

}  // namespace
}  // namespace cvtmesh
