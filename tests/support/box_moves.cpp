#include "tests/support/box_moves.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace cvtmesh::testing {

std::array<int, 4> box_moves(const TetMesh& m, const TetMesh& start, int n) {
  std::array<int, 4> moved{0, 0, 0, 0};
  const int nv = std::min(m.nb_vertices(), start.nb_vertices());
  for (int v = 0; v < nv; ++v) {
    const double *p = m.point(v), *p0 = start.point(v);
    int on = 0;
    for (int d = 0; d < 3; ++d) {
      const bool plane = p0[d] == 0 || p0[d] == n;
      on += plane;
      if (plane) EXPECT_NEAR(p[d], p0[d], 1e-12) << "vertex " << v << " left its plane";
      EXPECT_TRUE(p[d] >= -1e-12 && p[d] <= n + 1e-12) << "vertex " << v << " left the box";
    }
    const bool is_moved = p[0] != p0[0] || p[1] != p0[1] || p[2] != p0[2];
    if (on == 3) EXPECT_FALSE(is_moved) << "corner " << v << " moved";
    moved[on] += is_moved;
  }
  return moved;
}

}  // namespace cvtmesh::testing
