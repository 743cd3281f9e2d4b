// What a peer optimizer (Netgen, CGAL) must have kept for its column to count: a valid mesh
// (check_mesh: no inverted tet, closed boundary) with the input's boundary triangles exactly
// (the same coordinate triples and surface tags). Peers may remove or add interior vertices, so
// verify_optimized (which wants the vertex numbering) does not apply.
#pragma once
#include <string>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// Throws InvariantError naming `peer` and the first difference.
void verify_peer(const TetMesh& before, const TetMesh& after, const std::string& peer);

// Rebuilds vertex classes and node tags of `after` from `before` by exact coordinates: a vertex
// at the position of an input vertex takes its class and tag; any other is a new interior
// vertex of the region of one of its tets. Builds the adjacency.
void classify_peer_vertices(const TetMesh& before, TetMesh& after);

}  // namespace cvtmesh
