#include "core/mesh/build_adjacency.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/mesh/face_buckets.h"
#include "core/util/error.h"

namespace cvtmesh {

void build_adjacency(TetMesh& mesh) {
  const int nt = mesh.nb_tets(), nv = mesh.nb_vertices();
  mesh.adj.assign(4 * static_cast<std::size_t>(nt), -1);
  // The faces 4t+f, equal ones adjacent in increasing slot (face_buckets.h).
  const FaceBuckets fb =
      bucket_faces(nv, 4 * static_cast<std::size_t>(nt), [&](std::size_t i, std::uint32_t* k) {
        const int* tv = &mesh.tets[4 * (i / 4)];
        if (tv[0] < 0) return false;
        const int* lf = kTetFace[i % 4];
        std::uint32_t v[3] = {static_cast<std::uint32_t>(tv[lf[0]]),
                              static_cast<std::uint32_t>(tv[lf[1]]),
                              static_cast<std::uint32_t>(tv[lf[2]])};
        std::sort(v, v + 3);
        k[0] = v[0];
        k[1] = v[1];
        k[2] = v[2];
        return true;
      });
  // The first bucket holding a face of more than two tets (nv if none).
  int bad = nv;
#pragma omp parallel for schedule(dynamic, 4096) reduction(min : bad) if (nv > 4096)
  for (int a = 0; a < nv; ++a) {
    const FaceRecord *first = fb.begin_of(a), *last = fb.end_of(a);
    for (const FaceRecord* i = first; i < last;) {
      const FaceRecord* j = i + 1;
      while (j < last && same_face(*j, *i)) ++j;
      if (j - i > 2) {
        bad = std::min(bad, a);
      } else if (j - i == 2) {
        mesh.adj[i->id] = static_cast<int>((i + 1)->id);
        mesh.adj[(i + 1)->id] = static_cast<int>(i->id);
      }
      i = j;
    }
  }
  if (bad < nv) {
    const FaceRecord *first = fb.begin_of(bad), *last = fb.end_of(bad);
    for (const FaceRecord* i = first; i < last;) {
      const FaceRecord* j = i + 1;
      while (j < last && same_face(*j, *i)) ++j;
      if (j - i > 2)
        throw InputError("non-manifold volume mesh: a triangle (vertices " + std::to_string(bad) +
                         ", " + std::to_string(i->b) + ", " + std::to_string(i->c) +
                         ") is shared by " + std::to_string(j - i) + " tetrahedra");
      i = j;
    }
  }
}

}  // namespace cvtmesh
