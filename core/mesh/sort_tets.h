// Reorders the live tets of a mesh along a Morton (Z-order) curve of their centroids, so that
// tets close in space are close in memory (the Lloyd loop's per-tet and per-star passes then hit
// the cache). Tets have no identity: only their order changes. Dead slots are dropped.
#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// Keeps tet_region, tet_tags (when not empty) and the adjacency (when built) in step.
void sort_tets_spatially(TetMesh& mesh);

}  // namespace cvtmesh
