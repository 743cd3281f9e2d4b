// Completes a mesh read from a format that carries no Gmsh model (TetGen, Medit, VTK, surfaces):
// after it the mesh passes check_mesh and can be optimized or written as a Gmsh model.
#pragma once
#include <string>

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// data: dim 3 with tet.xyz, tet.tets (#T by 4, positively oriented), tet.tet_region and
// optionally tet.tris/tet.tri_surface; or dim 2 with tri.xy, tri.tris (#T by 3, counter-clockwise,
// or clockwise for a whole region), tri.tri_region and optionally tri.edges/tri.edge_curve.
// Steps:
//  - rejects non-finite coordinates, vertex ids out of range, repeated vertices in an element,
//    flat or inverted elements, duplicated or overlapping elements, non-manifold complexes;
//  - drops vertices no element uses (ids are renumbered; node_tags follow);
//  - region/surface/curve tags <= 0 get a fresh positive tag; facets (triangles in 3D, edges in
//    2D) with tag <= 0 inside one region are dropped; boundary facets missing from the input get a
//    fresh tag, missing interfaces between two regions another one;
//  - when data.model() has no entities (or no classification): classifies the vertices
//    (interior / on one surface / on a feature curve where two surfaces meet / corner) and creates
//    the matching Gmsh entities, with their boundaries, plus line and point elements for the
//    feature curves and corners;
//  - builds the adjacency and runs check_mesh.
// Throws InputError("<what>: <problem>").
void finish_mesh(MeshData& data, const std::string& what);

}  // namespace cvtmesh
