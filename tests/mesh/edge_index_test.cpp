// EdgeIndex: the lookup of an edge by its vertices, against a set of edge keys.
#include "core/mesh/edge_index.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

#include "core/mesh/face_key.h"

namespace cvtmesh {
namespace {

// Random edges (repeats and both orders included): find(u, w) is the first id of {u, w} in the
// list, either way round, and -1 for every other pair and for vertices out of range.
TEST(EdgeIndex, FindsTheFirstIdOfEachEdgeEitherWay) {
  std::mt19937 rng(3);
  const int nv = 40;
  std::vector<int> edges;
  std::map<EdgeKey, int> first;
  for (int e = 0; e < 120; ++e) {
    const int u = static_cast<int>(rng() % nv), w = static_cast<int>(rng() % nv);
    edges.insert(edges.end(), {u, w});
    first.emplace(edge_key(u, w), e);
  }
  const EdgeIndex index(edges, nv);
  int wrong = 0;
  for (int u = -1; u <= nv; ++u)
    for (int w = -1; w <= nv; ++w) {
      const auto it = first.find(edge_key(u, w));
      const int want = it == first.end() ? -1 : it->second;
      wrong += index.find(u, w) != want;
      wrong += index.contains(u, w) != (want >= 0);
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_FALSE(EdgeIndex().contains(0, 1));
}

}  // namespace
}  // namespace cvtmesh
