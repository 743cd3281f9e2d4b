// The discrete reference geometry: the input boundary triangulation itself. Its surface patches
// are the triangles of one Gmsh surface entity connected across edges where the surface turns by
// at most `feature_angle`; its curves are the chains of feature edges (edges between two patches,
// so Gmsh's own curves and the sharp edges inside an entity, e.g. the 12 edges of one STL box
// surface), split at corners. Closest points by CGAL AABB trees (triangle_set_distance.h).
//
// Roles: a vertex on no feature edge moves on its patch; on exactly two feature edges of one
// chain (and not a Gmsh point) it slides along the chain; anything else is a corner and is fixed,
// as is every vertex of a locked surface (curve) entity.
#pragma once
#include "core/mesh/bounding_box.h"  // bounding_box_diagonal, used with the boundary model
#include <vector>

#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// Built from the input mesh (its boundary triangles, tri_surface and vclass). The geometry keeps
// its own copy of what it needs. Throws std::invalid_argument for a negative feature angle.
BoundaryModel make_discrete_boundary(const TetMesh& input,
                                     const BoundaryModelOptions& options = {});

}  // namespace cvtmesh
