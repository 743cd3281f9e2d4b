#include "core/delaunay/cdt2d_locate.h"

#include <cstdint>

#include "core/geometry/predicates.h"

namespace cvtmesh {

Locate2dResult locate2d(const TriMesh2& mesh, const double* p, int start,
                        const std::vector<char>& stop, long max_steps) {
  Locate2dResult r;
  if (start < 0 || start >= mesh.nb_tris() || mesh.tris[3 * start] < 0) return r;
  const long cap = max_steps > 0 ? max_steps : 4L * mesh.nb_tris() + 16;
  std::uint32_t rng = 0x9E3779B9u;  // deterministic; randomised edge order avoids cycles
  int t = start;
  for (long step = 0; step <= cap; ++step) {
    const int* tv = &mesh.tris[3 * t];
    rng ^= rng << 13, rng ^= rng >> 17, rng ^= rng << 5;
    const int first = static_cast<int>(rng % 3);
    int next = -1;
    double o[3];
    for (int k = 0; k < 3; ++k) {
      const int e = (first + k) % 3;
      o[e] = orient2d(mesh.point(tv[(e + 1) % 3]), mesh.point(tv[(e + 2) % 3]), p);
      if (o[e] < 0) {
        next = e;
        break;
      }
    }
    if (next < 0) {
      r.tri = t;
      int zeros = 0, ze = -1;
      for (int e = 0; e < 3; ++e)
        if (o[e] == 0) ++zeros, ze = e;
      if (zeros == 1) {
        r.on_edge = ze;
      } else if (zeros >= 2) {
        for (int e = 0; e < 3; ++e)
          if (o[e] != 0) r.on_vertex = tv[e];
      }
      return r;
    }
    const int s = 3 * t + next;
    if (mesh.adj[s] < 0 || (!stop.empty() && stop[s])) return r;
    t = mesh.adj[s] / 3;
  }
  return r;
}

}  // namespace cvtmesh
