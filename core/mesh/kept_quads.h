// The quadrangles of a planar mesh (2D hybrid meshes: Gmsh's Recombine): kept verbatim in
// mesh.model.extra (blocks of dim 2, Gmsh type 3), their vertices fixed while the triangles are
// optimized (pin_vertices.h), their edges towards triangles constrained
// (constrain_kept_quad_edges.h), their interior vertices moved by smooth_quads2d.
// A surface's orientation is its triangles' (mesh.cw_surfaces); a surface of quadrangles only
// takes that of most of its quadrangles (orient_quad_surfaces, at read time).
#pragma once
#include <cstddef>
#include <vector>

#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

// The Gmsh element type of an order-1 quadrangle.
inline constexpr int kGmshQuad = 3;

struct KeptQuads {
  // #Q by 4 vertex ids, in the turning sense of their surface's triangles as stored
  // (counter-clockwise for a positive quadrangle: reversed for a surface of mesh.cw_surfaces).
  std::vector<int> quads;
  std::vector<int> entity;        // #Q surface tag
  std::vector<std::size_t> tags;  // #Q Gmsh element tag (0 if unknown)
  int nb_quads() const { return static_cast<int>(entity.size()); }
};

// Every order-1 quadrangle of mesh.model.extra, block by block.
KeptQuads kept_quads(const TriMesh2& mesh);

// Adds to mesh.cw_surfaces (kept sorted) every surface that has quadrangles and no triangle and
// whose quadrangles are mostly clockwise (signed area; ties counter-clockwise). Returns how many.
int orient_quad_surfaces(TriMesh2& mesh);

}  // namespace cvtmesh
