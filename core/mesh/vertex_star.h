// The star of a vertex (its incident tets, see vertex_tets.h) and its Delaunay neighbours.
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {

using VertexStar = VertexTets;  // built by vertex_tets

// The vertices sharing an edge with v (sorted, unique).
std::vector<int> vertex_neighbors(const TetMesh& mesh, const VertexStar& star, int v);

}  // namespace cvtmesh
