#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/boundary/collapse_boundary_edges.h"
#include "core/geometry/tet_geometry.h"
#include "core/mesh/vertex_tets.h"
#include "tests/support/test_meshes.h"
#include "tests/support/thread_counts.h"

namespace cvtmesh {
namespace {

// interior_spacing as one serial pass over the tets (its definition): each interior vertex's
// interior edge lengths summed in tet order, each tet's edges in kTetEdge order.
std::vector<double> one_pass(const TetMesh& m, const VertexTets& star) {
  const int nv = m.nb_vertices();
  auto interior = [&](int x) { return m.vclass[x].dim == 3; };
  std::vector<double> sum(nv, 0), count(nv, 0);
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* w = &m.tets[4 * static_cast<std::size_t>(t)];
    if (w[0] < 0) continue;
    for (const auto& e : kTetEdge) {
      const int a = w[e[0]], b = w[e[1]];
      if (!interior(a) || !interior(b)) continue;
      const double l = std::sqrt(dist2(m.point(a), m.point(b)));
      sum[a] += l, sum[b] += l;
      count[a] += 1, count[b] += 1;
    }
  }
  std::vector<double> s(nv, 0);
  for (int x = 0; x < nv; ++x) {
    if (interior(x)) continue;
    double total = 0, n = 0;
    for (const int* t = star.begin_of(x); t != star.end_of(x); ++t)
      for (int k = 0; k < 4; ++k) {
        const int y = m.tets[4 * static_cast<std::size_t>(*t) + k];
        if (interior(y) && count[y] > 0) total += sum[y] / count[y], n += 1;
      }
    s[x] = n > 0 ? total / n : 0;
  }
  return s;
}

TEST(InteriorSpacing, EqualsOnePassOverTheTetsBitForBitForAnyThreadCount) {
  const TetMesh m = testing::jittered_box(17, 0.3, 11);  // 5832 vertices: the parallel loops
  const VertexTets star = vertex_tets(m);
  const std::vector<double> want = one_pass(m, star);
  int nb_boundary = 0;
  for (int x = 0; x < m.nb_vertices(); ++x) nb_boundary += m.vclass[x].dim < 3 && want[x] > 0;
  ASSERT_GT(nb_boundary, 1000);
  for (const std::vector<double>& got :
       testing::for_each_thread_count([&] { return interior_spacing(m, star); }))
    EXPECT_EQ(got, want);  // exact equality of every double
}

}  // namespace
}  // namespace cvtmesh
