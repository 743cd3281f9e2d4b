// The curves' edges of a mesh classified on a model (set_model_curve_edges): a boundary edge is a
// curve's edge when one curve of the model holds both ends (a vertex on it or a corner bounding
// it), never when an end is on a surface; an unclassified end keeps the edge refused (a curve's
// edge may not be missed); pinned vertices are read through their encoded class; without model
// curves nothing is known.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "core/boundary/model_curve_edges.h"
#include "core/mesh/pin_vertices.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

// One tet: v0 a corner (point 1), v1 on curve 1 (points 1, 2), v2 on curve 2 (points 2, 3), v3 on
// surface 1; its four faces are the boundary triangles.
TetMesh classified_tet() {
  TetMesh m = testing::make_tet_mesh({{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}},
                                     {{{0, 1, 2, 3}}});
  m.vclass[0] = VertexClass{0, 1};
  m.vclass[1] = VertexClass{1, 1};
  m.vclass[2] = VertexClass{1, 2};
  m.vclass[3] = VertexClass{2, 1};
  m.model.entities = {{0, 1, {}}, {0, 2, {}}, {0, 3, {}}, {1, 1, {1, -2}}, {1, 2, {2, -3}}};
  return m;
}

bool listed(const BoundaryModel& b, int x, int y) {
  return b.curve_edges_known && b.may_be_curve_edge(x, y);
}

TEST(ModelCurveEdges, OneCurveHoldingBothEndsMakesACurveEdge) {
  const TetMesh m = classified_tet();
  BoundaryModel b;
  ASSERT_TRUE(set_model_curve_edges(m, b));
  EXPECT_TRUE(b.curve_edges_known);
  EXPECT_TRUE(listed(b, 0, 1));                           // the corner bounds curve 1, v1 is on it
  EXPECT_FALSE(listed(b, 1, 2));                          // two curves, a chord across the face
  EXPECT_FALSE(listed(b, 0, 2));                          // point 1 does not bound curve 2
  for (int x : {0, 1, 2}) EXPECT_FALSE(listed(b, x, 3));  // a surface end
  EXPECT_EQ(b.curve_edges, (std::vector<std::array<int, 2>>{{0, 1}}));
}

TEST(ModelCurveEdges, AnUnclassifiedEndKeepsTheEdgeACurveEdge) {
  TetMesh m = classified_tet();
  m.vclass[2] = VertexClass{1, 0};  // on an unknown curve
  BoundaryModel b;
  ASSERT_TRUE(set_model_curve_edges(m, b));
  EXPECT_TRUE(listed(b, 1, 2));
  EXPECT_TRUE(listed(b, 0, 2));
  EXPECT_FALSE(listed(b, 2, 3));
}

TEST(ModelCurveEdges, PinnedVerticesAreReadThroughTheirClass) {
  TetMesh m = classified_tet();
  BoundaryModel plain;
  ASSERT_TRUE(set_model_curve_edges(m, plain));
  // Every vertex pinned: the classes are encoded, the result the same.
  m.model.extra.push_back(ElementBlock{2, 9, 2, {1}, {0, 1, 2}, {}});
  ASSERT_GT(pin_vertices(m), 0);
  BoundaryModel pinned;
  ASSERT_TRUE(set_model_curve_edges(m, pinned));
  EXPECT_EQ(pinned.curve_edges, plain.curve_edges);
}

TEST(ModelCurveEdges, NoModelCurveLeavesTheModelUnknown) {
  TetMesh m = classified_tet();
  m.model.entities.clear();
  BoundaryModel b;
  EXPECT_FALSE(set_model_curve_edges(m, b));
  EXPECT_FALSE(b.curve_edges_known);
  EXPECT_TRUE(b.curve_edges.empty());
}

}  // namespace
}  // namespace cvtmesh
