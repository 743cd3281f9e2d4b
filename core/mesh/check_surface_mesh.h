// Validity of a surface mesh in space: a TetMesh without tets whose `tris` are the surface (an
// open shell, CAD faces that bound no volume: core/io/gmsh_surface_mesh3.h). check_mesh(TetMesh)
// calls it for a mesh with triangles and no tets.
#pragma once
#include <vector>

#include "core/mesh/check_mesh.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// True for a TetMesh that is a surface mesh: no tets, at least one triangle.
inline bool is_surface_mesh(const TetMesh& mesh) {
  return mesh.nb_tets() == 0 && mesh.nb_tris() > 0;
}

// Vertex ids in range, array sizes consistent, no flat triangle (three collinear vertices, exact
// orient2d on the three coordinate planes), no triangle listed twice in one surface entity (the
// same three vertices; two surfaces may share one, as the fillings of one curve loop do at a
// corner). MeshCheck::nb_inverted counts the flat triangles, nb_bad_adjacency the duplicates.
MeshCheck check_surface_mesh(const TetMesh& mesh);

// The pairs of triangles of one surface entity that share an edge (of exactly those two) and
// fold onto each other: their normals, taken consistently across the edge, turn by more than
// `max_turn_degrees` (the second triangle turned over onto the first). #P by 2 triangle ids.
std::vector<std::array<int, 2>> folded_triangle_pairs(const TetMesh& mesh,
                                                      double max_turn_degrees = 170);

}  // namespace cvtmesh
