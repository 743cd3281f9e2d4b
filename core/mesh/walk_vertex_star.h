// The star of one vertex (its incident live tets), found by walking the adjacency from one of
// them: O(size of the star), no O(#V + #T) work (compare vertex_tets.h, which does every vertex).
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// The tets holding v reachable from the live tet t (which holds v) through faces holding v, in
// breadth-first order from t: the whole star when the tets around v form one connected fan (an
// interior vertex, or a boundary vertex of a manifold mesh). Needs mesh.adj.
// Throws std::invalid_argument if t is dead or does not hold v.
std::vector<int> walk_vertex_star(const TetMesh& mesh, int t, int v);

}  // namespace cvtmesh
