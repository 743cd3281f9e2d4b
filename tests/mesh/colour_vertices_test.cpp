#include "core/mesh/colour_vertices.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/mesh/vertex_tets.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

// The colours of the interior vertices of a Gmsh mesh, no two sharing a tet: every listed vertex
// is coloured once, in the given order within its colour, no two vertices of a colour share a
// tet, each vertex's colour is the smallest its earlier neighbours leave free (greedy), and the
// colouring is the same when computed again.
TEST(ColourVertices, NoTwoVerticesOfAColourShareATetAndTheColouringIsGreedyInOrder) {
  const MeshData d = testing::cube_sphere(0.1, 0.08);
  const TetMesh& m = d.tet;
  const VertexTets star = vertex_tets(m);
  std::vector<int> order;
  for (int v = m.nb_vertices() - 1; v >= 0; --v)  // an order other than the ids'
    if (m.vclass[v].dim == 3) order.push_back(v);
  ASSERT_GT(order.size(), 100u);
  auto conflicts = [&](int v, std::vector<int>& out) {
    for (const int* t = star.begin_of(v); t != star.end_of(v); ++t)
      out.insert(out.end(), &m.tets[4 * *t], &m.tets[4 * *t] + 4);
  };
  const VertexColouring k = colour_vertices(m.nb_vertices(), order, conflicts);
  ASSERT_EQ(k.vertices.size(), order.size());
  ASSERT_GE(k.nb_colours(), 2);
  std::vector<int> colour(m.nb_vertices(), -1), position(m.nb_vertices(), -1);
  for (std::size_t i = 0; i < order.size(); ++i) position[order[i]] = static_cast<int>(i);
  for (int c = 0; c < k.nb_colours(); ++c) {
    EXPECT_GT(k.size_of(c), 0);
    for (const int* v = k.begin_of(c); v != k.end_of(c); ++v) {
      EXPECT_EQ(colour[*v], -1) << "vertex " << *v << " coloured twice";
      colour[*v] = c;
      if (v + 1 != k.end_of(c)) EXPECT_LT(position[*v], position[*(v + 1)]);
    }
  }
  std::vector<int> near;
  for (int v : order) {
    near.clear();
    conflicts(v, near);
    std::vector<char> taken(k.nb_colours(), 0);
    for (int w : near) {
      if (w == v || colour[w] < 0) continue;
      EXPECT_NE(colour[w], colour[v]) << "vertices " << v << " and " << w << " share a tet";
      if (position[w] < position[v]) taken[colour[w]] = 1;
    }
    for (int c = 0; c < colour[v]; ++c) EXPECT_TRUE(taken[c]) << "vertex " << v << " colour " << c;
  }
  const VertexColouring again = colour_vertices(m.nb_vertices(), order, conflicts);
  EXPECT_EQ(again.offset, k.offset);
  EXPECT_EQ(again.vertices, k.vertices);
}

}  // namespace
}  // namespace cvtmesh
