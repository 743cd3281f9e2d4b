// transfer_views: an input's node and element data carried onto another mesh of the same domain.
#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh/transfer_views.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

MeshData as_data(TetMesh m) {
  MeshData d;
  d.dim = 3;
  d.tet = std::move(m);
  return d;
}

double affine(const double* p) {
  return 1.5 * p[0] - 2 * p[1] + 0.25 * p[2] + 3;
}

TEST(TransferViews, LinearNodeFieldIsReproducedAndElementFieldFollowsTheCentroid) {
  MeshData from = as_data(testing::jittered_box(6, 0.2, 7));
  MeshData to = as_data(testing::jittered_box(9, 0.25, 11));  // another mesh of [0, 6]^3
  for (double& x : to.tet.xyz) x *= 6.0 / 9.0;
  const int nv = from.tet.nb_vertices(), nt = from.tet.nb_tets();
  DataView nodes;
  nodes.name = "affine";
  nodes.components = 2;
  nodes.times = {0.5};
  nodes.steps.resize(1);
  for (int v = 0; v < nv; ++v) {
    nodes.steps[0].push_back(affine(from.tet.point(v)));
    nodes.steps[0].push_back(-affine(from.tet.point(v)));
  }
  nodes.fingerprint = mesh_fingerprint(from);
  DataView cells;
  cells.name = "cell";
  cells.on_nodes = false;
  cells.times = {0};
  cells.steps.resize(1);
  for (int t = 0; t < nt; ++t) cells.steps[0].push_back(t);
  cells.fingerprint = mesh_fingerprint(from);
  DataView stale = nodes;
  stale.fingerprint ^= 1;  // of another mesh: left out
  from.model().views = {nodes, cells, stale};

  const std::vector<DataView> out = transfer_views(from, to);
  ASSERT_EQ(out.size(), 2u);
  const int nv2 = to.tet.nb_vertices(), nt2 = to.tet.nb_tets();
  EXPECT_EQ(out[0].name, "affine");
  EXPECT_EQ(out[0].fingerprint, mesh_fingerprint(to));
  EXPECT_EQ(out[0].times, nodes.times);
  ASSERT_EQ(out[0].steps.size(), 1u);
  ASSERT_EQ(out[0].steps[0].size(), 2u * nv2);
  double worst = 0;
  for (int v = 0; v < nv2; ++v) {
    worst = std::max(worst, std::abs(out[0].steps[0][2 * v] - affine(to.tet.point(v))));
    worst = std::max(worst, std::abs(out[0].steps[0][2 * v + 1] + affine(to.tet.point(v))));
  }
  EXPECT_LT(worst, 1e-9) << "an affine field is interpolated exactly";
  // Each element value names an input tet that holds the centroid.
  ASSERT_EQ(out[1].steps[0].size(), static_cast<std::size_t>(nt2));
  for (int t = 0; t < nt2; ++t) {
    double c[3] = {0, 0, 0};
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < 3; ++i) c[i] += to.tet.point(to.tet.tets[4 * t + k])[i] / 4;
    const double src = out[1].steps[0][t];
    ASSERT_TRUE(std::isfinite(src));
    const int s = static_cast<int>(src);
    ASSERT_GE(s, 0);
    ASSERT_LT(s, nt);
    // c inside tet s (all four sub-volumes non-negative, up to rounding).
    const double* p[4];
    for (int k = 0; k < 4; ++k) p[k] = from.tet.point(from.tet.tets[4 * s + k]);
    auto vol = [](const double* a, const double* b, const double* cc, const double* d) {
      double u[3], w[3], z[3];
      for (int i = 0; i < 3; ++i) {
        u[i] = b[i] - a[i];
        w[i] = cc[i] - a[i];
        z[i] = d[i] - a[i];
      }
      return u[0] * (w[1] * z[2] - w[2] * z[1]) - u[1] * (w[0] * z[2] - w[2] * z[0]) +
             u[2] * (w[0] * z[1] - w[1] * z[0]);
    };
    const double whole = vol(p[0], p[1], p[2], p[3]);
    EXPECT_GE(vol(c, p[1], p[2], p[3]) / whole, -1e-9) << t;
    EXPECT_GE(vol(p[0], c, p[2], p[3]) / whole, -1e-9) << t;
    EXPECT_GE(vol(p[0], p[1], c, p[3]) / whole, -1e-9) << t;
    EXPECT_GE(vol(p[0], p[1], p[2], c) / whole, -1e-9) << t;
  }
}

}  // namespace
}  // namespace cvtmesh
