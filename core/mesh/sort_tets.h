// Space-filling-curve orders for a tet mesh. Tets (by centroid) and free vertices are sorted along
// a Morton (Z-order) curve, so that what is close in space is close in memory (the Lloyd loop's
// per-tet and per-star passes then hit the cache).
// sort_tets_spatially: tets have no identity, only their order changes; dead slots are dropped.
#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// Keeps tet_region, tet_tags (when not empty) and the adjacency (when built) in step.
void sort_tets_spatially(TetMesh& mesh);

// Renumbers the free vertices (vclass.dim == 3) along the same kind of curve, within the ids the
// free vertices already have: fixed vertices keep their ids, every array follows
// (permute_vertices: coordinates, classification, node tags, tets). A free vertex keeps its node
// tag, so writing back to Gmsh is unchanged.
void sort_free_vertices_spatially(TetMesh& mesh);

// Renumbers every vertex along the curve (for a mesh whose vertex ids mean nothing outside, e.g. a
// frozen background mesh).
void sort_all_vertices_spatially(TetMesh& mesh);

}  // namespace cvtmesh
