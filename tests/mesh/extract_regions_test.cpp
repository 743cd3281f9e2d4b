// extract_regions / merge_regions: one volume as a mesh of its own, its interface pinned, and back.
#include "core/mesh/extract_regions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/mesh/check_mesh.h"
#include "core/mesh/merge_regions.h"
#include "core/util/error.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

TEST(ExtractRegions, OneVolumeIsAValidMeshWhoseInterfaceIsPinnedAndMergesBackUnchanged) {
  const TetMesh m = testing::cube_sphere(0.2, 0.15, false, {{"two_regions", 1}}).tet;
  const std::set<int> regions(m.tet_region.begin(), m.tet_region.end());
  ASSERT_EQ(regions.size(), 2u);
  const int ball = *regions.begin(), other = *regions.rbegin();
  const RegionSubmesh x = extract_regions(m, {ball});
  const long nb_ball = std::count(m.tet_region.begin(), m.tet_region.end(), ball);
  EXPECT_EQ(x.mesh.nb_tets(), nb_ball);
  EXPECT_TRUE(check_mesh(x.mesh).ok);
  // Every vertex shared with the other region is pinned (a corner with a marked entity).
  std::set<int> in_other;
  for (int t = 0; t < m.nb_tets(); ++t)
    if (m.tet_region[t] == other)
      for (int k = 0; k < 4; ++k) in_other.insert(m.tets[4 * t + k]);
  int pinned = 0;
  for (int i = 0; i < x.mesh.nb_vertices(); ++i) {
    const bool shared = in_other.count(x.to_parent[i]) > 0;
    EXPECT_EQ(x.mesh.vclass[i].entity < 0, shared) << i;
    pinned += shared;
  }
  EXPECT_EQ(pinned, x.nb_interface);
  EXPECT_GT(pinned, 0);
  // Back unchanged: the same tets (the other region's first, in order), the same vertices.
  TetMesh back = m;
  merge_regions(back, x, x.mesh);
  EXPECT_EQ(back.xyz, m.xyz);
  EXPECT_EQ(back.nb_tets(), m.nb_tets());
  EXPECT_TRUE(check_mesh(back).ok);
  std::vector<int> kept;
  for (int t = 0; t < m.nb_tets(); ++t)
    if (m.tet_region[t] == other) kept.insert(kept.end(), &m.tets[4 * t], &m.tets[4 * t] + 4);
  EXPECT_TRUE(std::equal(kept.begin(), kept.end(), back.tets.begin()));
  // A moved interface vertex is refused.
  TetMesh moved = x.mesh;
  for (int i = 0; i < moved.nb_vertices(); ++i)
    if (moved.vclass[i].entity < 0) {
      moved.point(i)[0] += 1e-3;
      break;
    }
  TetMesh again = m;
  EXPECT_THROW(merge_regions(again, x, moved), InvariantError);
}

}  // namespace
}  // namespace cvtmesh
