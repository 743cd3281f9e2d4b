// The constrained faces of a tet mesh (mesh.tris: boundary and interface triangles) as a hash set
// of sorted vertex triples, so that a local operation can refuse to remove one in O(1).
#pragma once
#include <unordered_set>

#include "core/mesh/face_key.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

using ConstrainedFaces = std::unordered_set<FaceKey, FaceKeyHash>;

// O(#F). Build it once per pass, not once per operation.
ConstrainedFaces constrained_faces(const TetMesh& mesh);

}  // namespace cvtmesh
