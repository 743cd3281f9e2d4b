// partition_tets: METIS's parts of the tets' dual graph, and the cut moved off a previous one.
#include "core/distributed/partition_tets.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/mesh/build_adjacency.h"
#include "core/util/error.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

// The vertices of the faces between tets of different parts.
std::vector<char> interface_vertices(const TetMesh& m, const std::vector<int>& part) {
  std::vector<char> on(m.nb_vertices(), 0);
  for (int t = 0; t < m.nb_tets(); ++t)
    for (int f = 0; f < 4; ++f) {
      const int a = m.adj[4 * t + f];
      if (a < 0 || part[a / 4] == part[t]) continue;
      for (int k = 0; k < 3; ++k) on[m.tets[4 * t + kTetFace[f][k]]] = 1;
    }
  return on;
}

TEST(PartitionTets, BalancedPartsCoverEveryTetAndAreTheSameEveryCall) {
  TetMesh m = testing::cube_sphere(0.12, 0.1).tet;
  build_adjacency(m);
  const int parts = 3;
  const TetPartition p = partition_tets(m, parts);
  ASSERT_EQ(p.part.size(), static_cast<std::size_t>(m.nb_tets()));
  std::vector<int> count(parts, 0);
  for (int x : p.part) {
    ASSERT_GE(x, 0);
    ASSERT_LT(x, parts);
    ++count[x];
  }
  for (int c : count) EXPECT_LE(c, 1.1 * m.nb_tets() / parts) << c;
  // The reported cut is the faces between parts, each counted once.
  int cut = 0;
  for (int t = 0; t < m.nb_tets(); ++t)
    for (int f = 0; f < 4; ++f) {
      const int a = m.adj[4 * t + f];
      cut += a >= 0 && a / 4 > t && p.part[a / 4] != p.part[t];
    }
  EXPECT_EQ(p.nb_cut_faces, cut);
  EXPECT_GT(cut, 0);
  EXPECT_EQ(p.nb_avoided_cut, 0);  // nothing to avoid
  EXPECT_EQ(partition_tets(m, parts).part, p.part);
}

TEST(PartitionTets, TheNextCutAvoidsThePreviousInterface) {
  TetMesh m = testing::cube_sphere(0.12, 0.1).tet;
  build_adjacency(m);
  const TetPartition first = partition_tets(m, 2);
  const std::vector<char> old = interface_vertices(m, first.part);
  // Without the weights METIS cuts the same way; with them, through none of the old vertices.
  EXPECT_EQ(partition_tets(m, 2, std::vector<char>(m.nb_vertices(), 0)).part, first.part);
  const TetPartition next = partition_tets(m, 2, old);
  EXPECT_EQ(next.nb_avoided_cut, 0);
  const std::vector<char> now = interface_vertices(m, next.part);
  for (int v = 0; v < m.nb_vertices(); ++v) EXPECT_FALSE(old[v] && now[v]) << v;
}

TEST(PartitionTets, RefusesMorePartsThanTets) {
  TetMesh m = testing::cube6();
  build_adjacency(m);
  EXPECT_THROW(partition_tets(m, m.nb_tets() + 1), InputError);
  EXPECT_THROW(partition_tets(m, 0), InputError);
  const TetPartition one = partition_tets(m, 1);
  EXPECT_EQ(std::count(one.part.begin(), one.part.end(), 0), m.nb_tets());
}

}  // namespace
}  // namespace cvtmesh
