// All triangulations of a convex n-gon, n = 3..7 (Catalan numbers 1, 2, 5, 14, 42): the tables
// behind edge removal (Gmsh BuildSwapPattern3..7, Shewchuk's "Two discrete optimization
// algorithms for the topological improvement of tetrahedral meshes").
#pragma once
#include <array>
#include <vector>

namespace cvtmesh {

struct PolygonTriangulations {
  int n = 0;
  // Every triangle (a, b, c), a < b < c, of polygon vertex ids 0..n-1: all C(n,3) of them.
  // Polygon vertices are in counter-clockwise order, so (a, b, c) is counter-clockwise too.
  std::vector<std::array<int, 3>> triangles;
  // Each triangulation: n-2 indices into `triangles`.
  std::vector<std::vector<int>> triangulations;
};

// The table for n = 3..7, computed once on first use (thread-safe). Throws std::invalid_argument
// for another n.
const PolygonTriangulations& polygon_triangulations(int n);

}  // namespace cvtmesh
