// The shared step of the free boundary's local repairs (restore_crossing_vertices,
// restore_hausdorff_vertices): boundary vertices go back to their input positions (exactly on the
// input boundary) where every tet of their star stays positively oriented (exact orient3d).
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {

// The live boundary triangles of mesh (#F by 3 vertex ids).
std::vector<int> live_boundary_tris(const TetMesh& mesh);

// `seeds` and `rings` rings of boundary neighbours around them (through the triangles `tris`),
// sorted, distinct.
std::vector<int> boundary_rings(int nb_vertices, const std::vector<int>& tris,
                                std::vector<int> seeds, int rings);

// Moves each vertex v of `vertices` (in order) with v < input.nb_vertices() that is not where the
// input has it back there if its star (`star`, valid for mesh's connectivity) stays positive;
// otherwise leaves it. Returns how many moved.
long restore_vertices_to_input(TetMesh& mesh, const TetMesh& input, const VertexTets& star,
                               const std::vector<int>& vertices);

}  // namespace cvtmesh
