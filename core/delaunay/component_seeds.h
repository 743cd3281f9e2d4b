// Region seeds for a constrained rebuild: one interior point per connected component of tets
// (tets joined across faces that are not constrained triangles), with the component's region
// tag. One seed per region is not enough: a closed internal surface (t14.geo's homology chains,
// an embedded shell) cuts a region into parts that TetGen's flood fill from a single seed does not
// reach, and their tets were dropped.
#pragma once
#include <array>
#include <utility>
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// (region tag, point) per component: the centroid of the component's fattest tet (by orient3d).
// Uses the vertex ids only (not the adjacency), on the current coordinates.
std::vector<std::pair<int, std::array<double, 3>>> component_seeds(const TetMesh& mesh);

}  // namespace cvtmesh
