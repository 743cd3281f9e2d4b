#include "core/mesh/sort_tets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <tuple>
#include <vector>

#include "core/mesh/check_mesh.h"
#include "core/swap/flip23.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

std::vector<std::tuple<std::array<int, 4>, int>> tet_set(const TetMesh& m) {
  std::vector<std::tuple<std::array<int, 4>, int>> s;
  for (int t = 0; t < m.nb_tets(); ++t) {
    if (m.tets[4 * t] < 0) continue;
    std::array<int, 4> k{m.tets[4 * t], m.tets[4 * t + 1], m.tets[4 * t + 2], m.tets[4 * t + 3]};
    std::sort(k.begin(), k.end());
    s.push_back({k, m.tet_region[t]});
  }
  std::sort(s.begin(), s.end());
  return s;
}

// Same tets (as oriented vertex sets, with their regions), valid adjacency, no dead slot; and
// neighbouring tets end up closer in memory than in Gmsh's order.
TEST(SortTets, KeepsTheTetsAndTheAdjacencyAndImprovesLocality) {
  MeshData d = testing::cube_sphere(0.1, 0.08, /*gmsh_optimize=*/false, {{"two_regions", 1}});
  TetMesh m = d.tet;
  // A flip leaves a dead slot or an appended tet: the sort must drop/keep them right.
  for (int t = 0; t < m.nb_tets(); ++t)
    if (flip23(m, t, 0).status == SwapStatus::kOk) break;
  const auto before = tet_set(m);
  auto gap = [](const TetMesh& mm) {
    double s = 0;
    long n = 0;
    for (int t = 0; t < mm.nb_tets(); ++t)
      for (int f = 0; f < 4; ++f)
        if (mm.tets[4 * t] >= 0 && mm.adj[4 * t + f] >= 0) {
          s += std::abs(mm.adj[4 * t + f] / 4 - t);
          ++n;
        }
    return s / static_cast<double>(n);
  };
  const double gap_before = gap(m);
  sort_tets_spatially(m);
  const MeshCheck c = check_mesh(m);
  ASSERT_TRUE(c.ok) << c.problems.front();
  EXPECT_EQ(tet_set(m), before);
  for (int t = 0; t < m.nb_tets(); ++t) EXPECT_GE(m.tets[4 * t], 0);
  EXPECT_LT(gap(m), gap_before);
}

// Free vertices change ids only among themselves; fixed vertices keep id and position; every
// node tag keeps its point; the tets are the same point sets.
TEST(SortFreeVertices, RenumbersOnlyFreeVerticesAndKeepsTagsWithPoints) {
  MeshData d = testing::cube_sphere(0.1, 0.08);
  TetMesh m = d.tet;
  ASSERT_EQ(m.node_tags.size(), static_cast<std::size_t>(m.nb_vertices()));
  const TetMesh before = m;
  sort_free_vertices_spatially(m);
  ASSERT_TRUE(check_mesh(m).ok);
  int moved = 0;
  for (int v = 0; v < m.nb_vertices(); ++v) {
    if (before.vclass[v].dim < 3) {
      EXPECT_EQ(m.vclass[v].dim, before.vclass[v].dim) << v;
      for (int k = 0; k < 3; ++k) EXPECT_EQ(m.point(v)[k], before.point(v)[k]) << v;
      EXPECT_EQ(m.node_tags[v], before.node_tags[v]) << v;
    } else {
      EXPECT_EQ(m.vclass[v].dim, 3) << v;
      moved += m.node_tags[v] != before.node_tags[v];
    }
  }
  EXPECT_GT(moved, 0);
  auto by_tag = [](const TetMesh& mm) {
    std::vector<std::tuple<std::size_t, double, double, double>> r;
    for (int v = 0; v < mm.nb_vertices(); ++v)
      r.push_back({mm.node_tags[v], mm.point(v)[0], mm.point(v)[1], mm.point(v)[2]});
    std::sort(r.begin(), r.end());
    return r;
  };
  EXPECT_EQ(by_tag(m), by_tag(before));
  auto tet_points = [](const TetMesh& mm) {
    std::vector<std::array<std::size_t, 4>> r;
    for (int t = 0; t < mm.nb_tets(); ++t) {
      std::array<std::size_t, 4> k;
      for (int j = 0; j < 4; ++j) k[j] = mm.node_tags[mm.tets[4 * t + j]];
      std::sort(k.begin(), k.end());
      r.push_back(k);
    }
    std::sort(r.begin(), r.end());
    return r;
  };
  EXPECT_EQ(tet_points(m), tet_points(before));
}

}  // namespace
}  // namespace cvtmesh

#include "core/swap/compact_tets.h"
#include "core/swap/flip32.h"

namespace cvtmesh {
namespace {

// compact_tets_fill: 3-2 flips leave dead slots in the middle of the array; filling them from the
// end keeps the same tets (with regions), a valid adjacency, and no dead slot.
TEST(CompactTetsFill, FillsHolesFromTheEndAndKeepsTheMeshValid) {
  MeshData d = testing::cube_sphere(0.1, 0.08, /*gmsh_optimize=*/false, {{"two_regions", 1}});
  TetMesh m = d.tet;
  int flips = 0;
  for (int t = 0; t < m.nb_tets() && flips < 25; ++t)
    for (int e = 0; e < 6 && m.tets[4 * t] >= 0; ++e)
      if (flip32(m, t, e).status == SwapStatus::kOk) ++flips;
  ASSERT_GT(flips, 3);
  const int slots = m.nb_tets();
  int dead = 0;
  for (int t = 0; t < slots; ++t) dead += m.tets[4 * t] < 0;
  ASSERT_EQ(dead, flips);
  const auto before = tet_set(m);
  EXPECT_EQ(compact_tets_fill(m), dead);
  EXPECT_EQ(m.nb_tets(), slots - dead);
  for (int t = 0; t < m.nb_tets(); ++t) EXPECT_GE(m.tets[4 * t], 0);
  const MeshCheck c = check_mesh(m);
  ASSERT_TRUE(c.ok) << c.problems.front();
  EXPECT_EQ(tet_set(m), before);
  EXPECT_EQ(compact_tets_fill(m), 0);
}

}  // namespace
}  // namespace cvtmesh
