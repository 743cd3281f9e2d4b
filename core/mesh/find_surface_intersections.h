// Pairs of surface triangles that intersect other than along their shared vertices and edge:
// a self-intersecting boundary (Gmsh's OCC booleans can leave one), a T-junction, a duplicate.
// TetGen cannot recover such a boundary (and its in-process rebuild may crash on one). Exact:
// every decision is a sign of orient3d / orient2d (core/geometry/predicates.h).
#pragma once
#include <array>
#include <vector>

namespace cvtmesh {

// xyz: #V by 3 coordinates. tris: #F by 3 vertex ids (0-based, any orientation).
// Returns the pairs (f < g) of triangle indices that intersect improperly, sorted, at most
// max_pairs of them (the search stops there).
std::vector<std::array<int, 2>> find_surface_intersections(const std::vector<double>& xyz,
                                                           const std::vector<int>& tris,
                                                           int max_pairs = 1000);

}  // namespace cvtmesh
