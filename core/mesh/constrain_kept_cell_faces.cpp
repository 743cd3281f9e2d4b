#include "core/mesh/constrain_kept_cell_faces.h"

#include <unordered_set>

#include "core/mesh/face_key.h"

namespace cvtmesh {

int constrain_kept_cell_faces(TetMesh& m) {
  // Triangular faces of the kept cells (Gmsh node orders: hexahedron 8, prism 6, pyramid 5).
  static const int kPrism[2][3] = {{0, 1, 2}, {3, 4, 5}};
  static const int kPyramid[4][3] = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  std::unordered_set<FaceKey, FaceKeyHash> cell_faces;
  std::vector<char> cell_vertex(m.nb_vertices(), 0);
  bool any = false;
  for (const ElementBlock& b : m.model.extra) {
    if (b.dim != 3) continue;
    any = true;
    // The order-2 kinds (hexahedron 27 / 20, prism 18 / 15, pyramid 14 / 13 nodes) have the
    // same corners first.
    const int type = b.gmsh_type;
    const int linear = type == 12 || type == 17   ? 5
                       : type == 13 || type == 18 ? 6
                       : type == 14 || type == 19 ? 7
                                                  : type;
    const int npe = linear == 5 ? 8 : linear == 6 ? 6 : linear == 7 ? 5 : 0;
    const int stride = type == 12   ? 27
                       : type == 17 ? 20
                       : type == 13 ? 18
                       : type == 18 ? 15
                       : type == 14 ? 14
                       : type == 19 ? 13
                                    : npe;
    if (!npe) continue;
    for (std::size_t e = 0; e + stride <= b.nodes.size(); e += stride) {
      const int* n = &b.nodes[e];
      for (int k = 0; k < npe; ++k) cell_vertex[n[k]] = 1;
      if (linear == 6)
        for (const auto& f : kPrism) cell_faces.insert(face_key(n[f[0]], n[f[1]], n[f[2]]));
      if (linear == 7)
        for (const auto& f : kPyramid) cell_faces.insert(face_key(n[f[0]], n[f[1]], n[f[2]]));
    }
  }
  if (!any) return 0;
  std::unordered_set<FaceKey, FaceKeyHash> have;
  for (int f = 0; f < m.nb_tris(); ++f)
    have.insert(face_key(m.tris[3 * f], m.tris[3 * f + 1], m.tris[3 * f + 2]));
  const bool tags = m.tri_tags.size() == static_cast<std::size_t>(m.nb_tris());
  int added = 0;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] < 0) continue;
    for (int f = 0; f < 4; ++f) {
      if (m.adj[4 * t + f] >= 0) continue;
      const int a = v[kTetFace[f][0]], b = v[kTetFace[f][1]], c = v[kTetFace[f][2]];
      const FaceKey k = face_key(a, b, c);
      if (have.count(k)) continue;
      // A face on a prism's or pyramid's triangle, or (non-conforming against a quadrangle
      // face) with its three vertices on kept cells.
      if (!cell_faces.count(k) && !(cell_vertex[a] && cell_vertex[b] && cell_vertex[c])) continue;
      m.tris.insert(m.tris.end(), {a, b, c});
      m.tri_surface.push_back(-1 - m.tet_region[t]);
      if (tags) m.tri_tags.push_back(0);
      have.insert(k);
      ++added;
    }
  }
  return added;
}

}  // namespace cvtmesh
