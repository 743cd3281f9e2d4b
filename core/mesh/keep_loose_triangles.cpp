#include "core/mesh/keep_loose_triangles.h"

#include <map>
#include <unordered_set>

#include "core/mesh/face_key.h"

namespace cvtmesh {

int keep_loose_triangles(TetMesh& m) {
  std::unordered_set<FaceKey, FaceKeyHash> faces;
  faces.reserve(4 * static_cast<std::size_t>(m.nb_tets()));
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] < 0) continue;
    for (int f = 0; f < 4; ++f)
      faces.insert(face_key(v[kTetFace[f][0]], v[kTetFace[f][1]], v[kTetFace[f][2]]));
  }
  const bool tags = m.tri_tags.size() == static_cast<std::size_t>(m.nb_tris());
  std::vector<int> tris, surface;
  std::vector<std::size_t> tri_tags;
  std::map<int, ElementBlock> loose;  // by surface entity
  int moved = 0;
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* v = &m.tris[3 * f];
    if (faces.count(face_key(v[0], v[1], v[2]))) {
      tris.insert(tris.end(), v, v + 3);
      surface.push_back(m.tri_surface[f]);
      if (tags) tri_tags.push_back(m.tri_tags[f]);
      continue;
    }
    ElementBlock& b = loose[m.tri_surface[f]];
    b.dim = 2;
    b.entity = m.tri_surface[f];
    b.gmsh_type = 2;
    b.tags.push_back(tags ? m.tri_tags[f] : 0);
    b.nodes.insert(b.nodes.end(), v, v + 3);
    ++moved;
  }
  if (!moved) return 0;
  m.tris = std::move(tris);
  m.tri_surface = std::move(surface);
  m.tri_tags = std::move(tri_tags);
  for (auto& [s, b] : loose) m.model.extra.push_back(std::move(b));
  return moved;
}

}  // namespace cvtmesh
