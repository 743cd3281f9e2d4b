#include "core/mesh/keep_loose_triangles.h"

#include <map>
#include <unordered_set>
#include <vector>

#include "core/mesh/face_key.h"

namespace cvtmesh {

int keep_loose_triangles(TetMesh& m) {
  // The triangles' keys, and the tet faces among them (a face is looked up only when its three
  // vertices are triangles' vertices: O(surface) hash work, not O(4 tets)).
  std::unordered_set<FaceKey, FaceKeyHash> keys, faces;
  std::vector<char> on_tri(static_cast<std::size_t>(m.nb_vertices()), 0);
  keys.reserve(static_cast<std::size_t>(m.nb_tris()));
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* v = &m.tris[3 * f];
    keys.insert(face_key(v[0], v[1], v[2]));
    for (int k = 0; k < 3; ++k) on_tri[v[k]] = 1;
  }
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] < 0) continue;
    for (int f = 0; f < 4; ++f) {
      const int a = v[kTetFace[f][0]], b = v[kTetFace[f][1]], c = v[kTetFace[f][2]];
      if (!on_tri[a] || !on_tri[b] || !on_tri[c]) continue;
      const FaceKey k = face_key(a, b, c);
      if (keys.count(k)) faces.insert(k);
    }
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
