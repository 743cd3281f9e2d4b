// Voronoi-cell centroids in 2D: micro-configurations with results computed by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "core/cvt/voronoi_centroids2d.h"
#include "core/mesh/check_mesh.h"

namespace cvtmesh {
namespace {

// A regular hexagon of circumradius 1 around a centre vertex (id 0), translated by (tx, ty).
TriMesh2 hexagon(double tx, double ty) {
  TriMesh2 m;
  m.xy = {tx, ty};
  m.vclass = {VertexClass{2, 1}};
  for (int k = 0; k < 6; ++k) {
    m.xy.push_back(tx + std::cos(M_PI / 3 * k));
    m.xy.push_back(ty + std::sin(M_PI / 3 * k));
    m.vclass.push_back(VertexClass{1, 1});
    m.tris.insert(m.tris.end(), {0, 1 + k, 1 + (k + 1) % 6});
    m.tri_region.push_back(1);
    m.edges.insert(m.edges.end(), {1 + k, 1 + (k + 1) % 6});
    m.edge_curve.push_back(1);
  }
  build_adjacency2(m);
  return m;
}

TEST(VoronoiCentroids2d, RegularHexagonCellCentroidIsItsGenerator) {
  const TriMesh2 m = hexagon(3.7, -1.2);
  ASSERT_TRUE(check_mesh(m).ok);
  const auto cells = voronoi_centroids2d(m);
  ASSERT_EQ(cells.size(), 7u);
  // The centre's cell: the regular hexagon of the six circumcentres (circumradius R = 1/sqrt 3),
  // area (3 sqrt3 / 2) R^2 = sqrt3 / 2, polar moment (5 sqrt3 / 8) R^4 = 5 sqrt3 / 72.
  EXPECT_NEAR(cells[0].centroid[0], 3.7, 1e-12);
  EXPECT_NEAR(cells[0].centroid[1], -1.2, 1e-12);
  EXPECT_NEAR(cells[0].mass, std::sqrt(3.0) / 2, 1e-12);
  EXPECT_NEAR(cells[0].energy, 5 * std::sqrt(3.0) / 72, 1e-12);
  // The cells partition the domain: the masses add up to the hexagon's area 3 sqrt3 / 2.
  double total = 0;
  for (const auto& c : cells) total += c.mass;
  EXPECT_NEAR(total, 3 * std::sqrt(3.0) / 2, 1e-12);
  // A density with the hexagon's symmetry (radial) keeps the centroid at the generator and goes
  // through the quadrature path: mass = int (1 + r^2) over the cell.
  const auto radial = voronoi_centroids2d(m, [](const double* x) {
    const double dx = x[0] - 3.7, dy = x[1] + 1.2;
    return 1 + dx * dx + dy * dy;
  });
  EXPECT_NEAR(radial[0].centroid[0], 3.7, 1e-12);
  EXPECT_NEAR(radial[0].centroid[1], -1.2, 1e-12);
  EXPECT_NEAR(radial[0].mass, std::sqrt(3.0) / 2 + 5 * std::sqrt(3.0) / 72, 1e-12);
}

// The rectangle [0,4] x [0,1] (corners fixed) with one interior generator p = (1, 0.5). Its
// Voronoi region is bounded by the bisectors with the corners:
//   (0,0): 2x + y >= 1.25     (0,1): 2x - y >= 0.25
//   (4,0): 6x - y <= 14.75    (4,1): 6x + y <= 15.75
// and reaches beyond y = 0 and y = 1, so it is clipped by the rectangle. The clipped cell is the
// hexagon (0.625,0) (59/24,0) (61/24,0.5) (59/24,1) (0.625,1) (0.375,0.5).
TEST(VoronoiCentroids2d, ClippedCellByHand) {
  TriMesh2 m;
  m.xy = {0, 0, 4, 0, 4, 1, 0, 1, 1, 0.5};
  m.vclass = {VertexClass{0, 1}, VertexClass{0, 2}, VertexClass{0, 3}, VertexClass{0, 4},
              VertexClass{2, 1}};
  m.tris = {4, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0};
  m.tri_region = {1, 1, 1, 1};
  m.edges = {0, 1, 1, 2, 2, 3, 3, 0};
  m.edge_curve = {1, 2, 3, 4};
  build_adjacency2(m);
  ASSERT_TRUE(check_mesh(m).ok);
  const double poly[6][2] = {{0.625, 0},     {59.0 / 24, 0}, {61.0 / 24, 0.5},
                             {59.0 / 24, 1}, {0.625, 1},     {0.375, 0.5}};
  double area = 0, cx = 0, cy = 0;  // shoelace
  for (int i = 0; i < 6; ++i) {
    const double* a = poly[i];
    const double* b = poly[(i + 1) % 6];
    const double c = a[0] * b[1] - b[0] * a[1];
    area += c / 2;
    cx += (a[0] + b[0]) * c / 6;
    cy += (a[1] + b[1]) * c / 6;
  }
  cx /= area, cy /= area;
  const auto cells = voronoi_centroids2d(m);
  EXPECT_NEAR(cells[4].mass, area, 1e-12);
  EXPECT_NEAR(cells[4].centroid[0], cx, 1e-12);
  EXPECT_NEAR(cells[4].centroid[1], cy, 1e-12);
  EXPECT_NEAR(cells[4].centroid[1], 0.5, 1e-12);  // symmetric about y = 0.5
  EXPECT_GT(cells[4].centroid[0], 1.0);           // pulled towards the far corners
  double total = 0;
  for (const auto& c : cells) total += c.mass;
  EXPECT_NEAR(total, 4.0, 1e-12);  // the clipped cells partition the rectangle
}

}  // namespace
}  // namespace cvtmesh
