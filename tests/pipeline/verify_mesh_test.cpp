// verify_optimized detects each kind of violation: a tampered `after` mesh throws InvariantError
// naming the problem, the untouched mesh passes.
#include "core/pipeline/verify_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/mesh/check_mesh.h"
#include "core/swap/insert_vertex.h"
#include "core/util/error.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

// Two Kuhn cubes side by side, [0,1]^3 (region 1) and [1,2]x[0,1]^2 (region 2): the outer
// boundary on surface 1, the shared square x = 1 (two triangles) on surface 99; groups "left"
// (region 1), "right" (region 2) and "walls" (surface 1), and two point elements.
TetMesh two_cubes() {
  std::vector<std::array<double, 3>> pts;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 4; ++i) pts.push_back({double(c), double(i & 1), double((i >> 1) & 1)});
  // Vertex (c, y, z) is 4c + y + 2z; the Kuhn cube from (c,0,0) to (c+1,1,1).
  std::vector<std::array<int, 4>> tets;
  for (int c = 0; c < 2; ++c) {
    auto id = [c](int x, int y, int z) { return 4 * (c + x) + y + 2 * z; };
    const int o = id(0, 0, 0), t = id(1, 1, 1);
    tets.insert(tets.end(), {{o, id(1, 0, 0), id(1, 1, 0), t},
                             {o, id(1, 0, 0), id(1, 0, 1), t},
                             {o, id(0, 1, 0), id(1, 1, 0), t},
                             {o, id(0, 1, 0), id(0, 1, 1), t},
                             {o, id(0, 0, 1), id(1, 0, 1), t},
                             {o, id(0, 0, 1), id(0, 1, 1), t}});
  }
  TetMesh m = testing::make_tet_mesh(pts, tets);
  for (int t = 6; t < 12; ++t) m.tet_region[t] = 2;
  // The interface x = 1: faces of region-1 tets whose three vertices have x = 1.
  for (int t = 0; t < 6; ++t)
    for (int f = 0; f < 4; ++f) {
      int on = 0;
      for (int k = 0; k < 3; ++k) on += m.point(m.tets[4 * t + kTetFace[f][k]])[0] == 1.0;
      if (on == 3) {
        for (int k = 0; k < 3; ++k) m.tris.push_back(m.tets[4 * t + kTetFace[f][k]]);
        m.tri_surface.push_back(99);
      }
    }
  m.model.entities = {{0, 1, {}},  {0, 2, {}},      {2, 1, {}},
                      {2, 99, {}}, {3, 1, {1, 99}}, {3, 2, {1, -99}}};
  m.model.groups = {{3, 10, "left", {1}}, {3, 11, "right", {2}}, {2, 12, "walls", {1}}};
  m.model.extra = {{0, 1, 15, {101}, {0}}, {0, 2, 15, {102}, {11}}};
  return m;
}

std::string violation(const TetMesh& before, const TetMesh& after) {
  try {
    verify_optimized(before, after);
  } catch (const InvariantError& e) {
    return e.what();
  }
  return "";
}

TEST(VerifyOptimized, TheTwoCubesAreValidAndPass) {
  const TetMesh m = two_cubes();
  const MeshCheck c = check_mesh(m);
  ASSERT_TRUE(c.ok) << c.problems.front();
  ASSERT_EQ(m.nb_tris(), 2 * 2 * 5 + 2);  // 5 outer squares per cube, the interface square
  const auto v = region_volumes(m);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_NEAR(v[0].second, 1.0, 1e-15);
  EXPECT_EQ(v[1].second, v[0].second);  // the same shape translated: the same rounding
  EXPECT_EQ(violation(m, m), "");
}

TEST(VerifyOptimized, DetectsASurfaceTriangleTurnedOverOnlyWhereItsSurfaceFacedOneWay) {
  // The outer surface (1) faces one way around the volume: one of its triangles reversed is
  // refused, with the boundary fixed or free. Made mixed in `before` too, nothing is claimed.
  const TetMesh m = two_cubes();
  TetMesh turned = m;
  std::swap(turned.tris[1], turned.tris[2]);
  ASSERT_EQ(turned.tri_surface[0], 1);
  EXPECT_NE(violation(m, turned).find("triangles of surface 1 were turned over"),
            std::string::npos);
  VerifyOptions free;
  free.boundary_moves = true;
  EXPECT_THROW(verify_optimized(m, turned, free), InvariantError);
  EXPECT_EQ(violation(turned, turned), "");
  // The interface (99): its sense is taken around region 1's tets; reversing it is refused too.
  TetMesh iface = m;
  const int f = m.nb_tris() - 1;
  ASSERT_EQ(iface.tri_surface[f], 99);
  std::swap(iface.tris[3 * f + 1], iface.tris[3 * f + 2]);
  EXPECT_NE(violation(m, iface).find("surface 99"), std::string::npos);
}

TEST(VerifyOptimized, AcceptsANewVertexInsideARegionOnlyIfClassifiedSo) {
  const TetMesh m = two_cubes();
  // The centre of the left cube joined to its 12 boundary triangles (insert_vertex).
  TetMesh after = m;
  std::vector<int> left = {0, 1, 2, 3, 4, 5};
  const double centre[3] = {0.5, 0.5, 0.5};
  SwapPlan plan = plan_insert_vertex(after, left, centre);
  ASSERT_EQ(plan.status, SwapStatus::kOk);
  const int v = insert_vertex(after, plan, centre);
  EXPECT_EQ(violation(m, after), "");
  TetMesh wrong = after;
  wrong.vclass[v].dim = 2;  // a new vertex on a surface: not allowed
  EXPECT_NE(violation(m, wrong).find("new vertex"), std::string::npos) << violation(m, wrong);
  wrong = after;
  wrong.vclass[v].entity = 2;  // classified in the other region
  EXPECT_NE(violation(m, wrong).find("new vertex"), std::string::npos) << violation(m, wrong);
  wrong = after;
  for (int t = 0; t < wrong.nb_tets(); ++t)  // one of its tets moved to region 2
    if (std::count(&wrong.tets[4 * t], &wrong.tets[4 * t] + 4, v)) {
      wrong.tet_region[t] = 2;
      break;
    }
  EXPECT_NE(violation(m, wrong), "");
  // Lost vertices are refused as before.
  TetMesh fewer = m;
  EXPECT_EQ(violation(after, fewer).find("lost vertices") != std::string::npos, true);
}

TEST(VerifyOptimized, DetectsAMissingOrChangedPhysicalGroup) {
  const TetMesh before = two_cubes();
  TetMesh after = before;
  after.model.groups.pop_back();
  EXPECT_NE(violation(before, after).find("physical groups changed"), std::string::npos);
  after = before;
  after.model.groups[2].tag = 13;  // "walls" renumbered
  EXPECT_NE(violation(before, after).find("\"walls\") disappeared"), std::string::npos);
  after = before;
  after.model.groups[1].entities = {1, 2};
  EXPECT_NE(violation(before, after).find("\"right\") changed its name or entities"),
            std::string::npos);
  after = before;
  after.model.groups[0].name = "Left";
  EXPECT_NE(violation(before, after).find("changed its name or entities"), std::string::npos);
}

TEST(VerifyOptimized, DetectsAVolumeGroupBoundedByOtherTriangles) {
  // The two regions exchange their tets: same volumes (both 1), same triangles and surfaces, a
  // valid mesh, but "left" now lies at x in [1,2].
  const TetMesh before = two_cubes();
  TetMesh after = before;
  for (int& r : after.tet_region) r = 3 - r;
  ASSERT_TRUE(check_mesh(after).ok);
  EXPECT_NE(violation(before, after).find("\"left\") is no longer bounded by the same triangles"),
            std::string::npos)
      << violation(before, after);  // The same with a `before` whose adjacency is not built (the
                                    // boundaries are then found by
  // sorting the faces): same answers.
  TetMesh no_adj = before;
  no_adj.adj.clear();
  EXPECT_EQ(violation(no_adj, before), "");
  EXPECT_NE(violation(no_adj, after).find("is no longer bounded by the same triangles"),
            std::string::npos);
}

TEST(VerifyOptimized, DetectsChangedEntitiesAndPointElements) {
  const TetMesh before = two_cubes();
  TetMesh after = before;
  after.model.entities[5].boundary = {1};  // region 2 no longer bounded by the interface
  EXPECT_NE(violation(before, after).find("entities or their boundaries changed"),
            std::string::npos);
  after = before;
  after.model.extra[1].nodes = {10};
  EXPECT_NE(violation(before, after).find("point or line elements changed"), std::string::npos);
  // The seam of a periodic surface listed once instead of as +c and -c, and renumbered element
  // tags, are not changes.
  TetMesh seam = before;
  seam.model.entities[5].boundary = {1, 99, -99};
  seam.model.extra[0].tags = {7};
  EXPECT_EQ(violation(seam, before), "");
}

TEST(VerifyOptimized, DetectsARegionVolumeChangeOfAFewTimes1e12) {
  // A vertex wrongly classified as interior moves although it is a corner: the triangles keep
  // their vertex ids, so only the volumes can tell. Moving corner (2,1,1) by 1e-11 along x (out
  // of the face x = 2, whose two triangles it is on) adds a cone of volume 1e-11 / 3 to region 2.
  const TetMesh before = two_cubes();
  TetMesh b2 = before;
  b2.vclass[11] = VertexClass{3, 2};
  ASSERT_EQ(b2.point(11)[0], 2.0);
  TetMesh after = b2;
  after.point(11)[0] += 1e-11;
  ASSERT_TRUE(check_mesh(after).ok);
  const auto vb = region_volumes(b2), va = region_volumes(after);
  const double rel = (va[1].second - vb[1].second) / vb[1].second;
  EXPECT_GT(rel, 1e-12);
  EXPECT_LT(rel, 1e-11);
  EXPECT_NE(violation(b2, after).find("volume of region 2 changed"), std::string::npos);
  // A move of the same vertex by 1e-14: below the tolerance.
  after = b2;
  after.point(11)[0] += 1e-14;
  EXPECT_EQ(violation(b2, after), "");
}

TEST(VerifyOptimized, DetectsAMissingOrChangedSurfaceGroupIn2D) {
  TriMesh2 before = testing::square2();
  before.model.entities = {{1, 1, {}}, {1, 2, {}}, {1, 3, {}}, {1, 4, {}}, {2, 1, {1, 2, 3, 4}}};
  before.model.groups = {{2, 5, "plate", {1}}, {1, 6, "bottom", {1}}};
  EXPECT_NO_THROW(verify_optimized(before, before));
  TriMesh2 after = before;
  after.model.groups.erase(after.model.groups.begin());
  EXPECT_THROW(verify_optimized(before, after), InvariantError);
  after = before;
  after.model.groups[1].entities = {2};
  EXPECT_THROW(verify_optimized(before, after), InvariantError);
}

// Two separate tets; moving a corner of the second into the first makes their boundaries cross:
// refused with the pair named. A crossing the input already had is not the optimizer's doing.
TEST(VerifyNoNewSurfaceCrossing, RefusesACrossingTheInputDidNotHave) {
  const TetMesh input = testing::make_tet_mesh(
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0}, {3, 0, 0}, {2, 1, 0}, {2, 0, 1}},
      {{0, 1, 2, 3}, {4, 5, 6, 7}});
  EXPECT_NO_THROW(verify_no_new_surface_crossing(input, input));
  TetMesh moved = input;
  moved.xyz[3 * 4 + 0] = 0.2, moved.xyz[3 * 4 + 1] = 0.2, moved.xyz[3 * 4 + 2] = 0.2;
  ASSERT_TRUE(check_mesh(moved).ok);  // each tet still positive: only the surfaces cross
  try {
    verify_no_new_surface_crossing(input, moved);
    ADD_FAILURE() << "a crossing boundary passed";
  } catch (const InvariantError& e) {
    EXPECT_NE(std::string(e.what()).find("self-intersect (first: boundary triangles"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(verify_no_new_surface_crossing(moved, moved));
}

}  // namespace
}  // namespace cvtmesh
