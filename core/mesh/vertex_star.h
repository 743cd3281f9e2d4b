// Vertex -> incident tets, as compressed rows (CSR): the tets around v are
// tet[offset[v] .. offset[v+1]).
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct VertexStar {
  std::vector<int> offset;  // #V + 1
  std::vector<int> tet;     // 4 * #live tets
};

VertexStar build_vertex_star(const TetMesh& mesh);

// The vertices sharing an edge with v (sorted, unique).
std::vector<int> vertex_neighbors(const TetMesh& mesh, const VertexStar& star, int v);

}  // namespace cvtmesh
