#include "core/mesh/vertex_tets.h"

#include <gtest/gtest.h>

#include <vector>

#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

// The stars of a few vertices are exactly their stars in the full incidence, the others empty,
// and a dead tet slot is in nobody's star.
TEST(VertexTets, StarsOfSomeVerticesMatchTheFullIncidence) {
  MeshData d = testing::cube_sphere(0.2, 0.15);
  TetMesh& m = d.tet;
  m.tets[0] = m.tets[1] = m.tets[2] = m.tets[3] = -1;  // a dead slot
  const VertexTets all = vertex_tets(m);
  std::vector<int> some;
  for (int v = 0; v < m.nb_vertices(); v += 7) some.push_back(v);
  const VertexTets part = vertex_tets_of(m, some);
  ASSERT_EQ(part.offset.size(), all.offset.size());
  std::vector<char> chosen(m.nb_vertices(), 0);
  for (int v : some) chosen[v] = 1;
  int nonempty = 0;
  for (int v = 0; v < m.nb_vertices(); ++v) {
    const std::vector<int> a(all.begin_of(v), all.end_of(v)), p(part.begin_of(v), part.end_of(v));
    if (chosen[v]) {
      EXPECT_EQ(p, a) << "vertex " << v;
      nonempty += !p.empty();
    } else {
      EXPECT_TRUE(p.empty()) << "vertex " << v;
    }
    for (int t : a) EXPECT_NE(t, 0);
  }
  EXPECT_GT(nonempty, 10);
}

}  // namespace
}  // namespace cvtmesh
