#include "core/cvt/sizing_field3.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh/vertex_tets.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

// The mesh sizing field at a background vertex is that vertex's value whatever the location hint:
// none, a tet at the vertex, or a tet on the far side of the ball (cube_sphere without the ball is
// not convex: a straight walk from there leaves the mesh through the hole). And at points inside
// tets it interpolates the same value from any hint (a hint is any tet id of the background, which
// keeps its own order).
TEST(SizingField3, MeshSizingDoesNotDependOnTheHintInANonConvexDomain) {
  MeshData d = testing::cube_sphere(0.08, 0.06);
  const TetMesh& m = d.tet;
  const auto s = make_mesh_sizing3(m);
  const VertexTets vt = vertex_tets(m);
  // A tet near the corner (0,0,0), on the other side of the ball from the far corner.
  int corner_tet = -1;
  double best = 1e300;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const double* p = m.point(m.tets[4 * t]);
    const double r = p[0] + p[1] + p[2];
    if (r < best) best = r, corner_tet = t;
  }
  int checked = 0;
  for (int v = 0; v < m.nb_vertices(); ++v) {
    if (vt.nb_tets_of(v) == 0) continue;
    double g[3];
    int at_vertex = vt.begin_of(v)[0], none = -1, far = corner_tet;
    const double h = s->eval(m.point(v), g, &at_vertex);
    EXPECT_NEAR(s->eval(m.point(v), g, &none), h, 1e-12 * h) << "vertex " << v;
    EXPECT_NEAR(s->eval(m.point(v), g, &far), h, 1e-12 * h) << "vertex " << v;
    ++checked;
  }
  EXPECT_GT(checked, 1000);
  for (int t = 0; t < m.nb_tets(); t += 5) {
    double c[3] = {0, 0, 0};
    for (int k = 0; k < 4; ++k)
      for (int dd = 0; dd < 3; ++dd) c[dd] += 0.25 * m.point(m.tets[4 * t + k])[dd];
    double g[3];
    int in = t, far = corner_tet;
    const double h = s->eval(c, g, &in);
    int again = in;  // the hint returned is where the point is: found again at once
    EXPECT_NEAR(s->eval(c, g, &again), h, 1e-12 * h);
    EXPECT_EQ(again, in);
    EXPECT_NEAR(s->eval(c, g, &far), h, 1e-12 * h) << "tet " << t;
  }
}

}  // namespace
}  // namespace cvtmesh
