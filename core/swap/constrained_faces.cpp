#include "core/swap/constrained_faces.h"

namespace cvtmesh {

ConstrainedFaces constrained_faces(const TetMesh& mesh) {
  ConstrainedFaces set;
  set.reserve(static_cast<std::size_t>(mesh.nb_tris()) * 2);
  for (int f = 0; f < mesh.nb_tris(); ++f)
    set.insert(face_key(mesh.tris[3 * f], mesh.tris[3 * f + 1], mesh.tris[3 * f + 2]));
  return set;
}

}  // namespace cvtmesh
