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

// Above the size at which the stars are built in parallel: the same arrays as one pass in tet
// order (each star increasing), dead slots in no star, for any thread count.
TEST(VertexTets, LargeMeshesGiveTheStarsOfOnePassInTetOrder) {
  TetMesh m;
  const int nv = 50000, nt = 260000;
  m.xyz.assign(3 * static_cast<std::size_t>(nv), 0.0);
  m.vclass.resize(nv);
  m.tets.resize(4 * static_cast<std::size_t>(nt));
  m.tet_region.assign(nt, 1);
  unsigned s = 12345;
  auto next = [&] { return (s = s * 1103515245u + 12345u) >> 8; };
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 4; ++k) m.tets[4 * static_cast<std::size_t>(t) + k] = next() % nv;
  for (int t = 0; t < nt; t += 97) m.tets[4 * static_cast<std::size_t>(t)] = -1;
  std::vector<std::vector<int>> expected(nv);
  for (int t = 0; t < nt; ++t) {
    const int* tv = &m.tets[4 * static_cast<std::size_t>(t)];
    if (tv[0] < 0) continue;
    for (int k = 0; k < 4; ++k) expected[tv[k]].push_back(t);
  }
  std::vector<int> some;
  for (int v = 0; v < nv; v += 5) some.push_back(v);
  const VertexTets all = vertex_tets(m), part = vertex_tets_of(m, some);
  ASSERT_EQ(all.offset.size(), static_cast<std::size_t>(nv) + 1);
  for (int v = 0; v < nv; ++v) {
    ASSERT_EQ(std::vector<int>(all.begin_of(v), all.end_of(v)), expected[v]) << "vertex " << v;
    const std::vector<int> p(part.begin_of(v), part.end_of(v));
    if (v % 5 == 0)
      ASSERT_EQ(p, expected[v]) << "vertex " << v;
    else
      ASSERT_TRUE(p.empty()) << "vertex " << v;
  }
}

}  // namespace
}  // namespace cvtmesh
