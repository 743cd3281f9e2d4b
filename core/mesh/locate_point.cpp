#include "core/mesh/locate_point.h"

#include "core/geometry/predicates.h"
#include "core/geometry/tet_geometry.h"

namespace cvtmesh {

LocateResult locate_point(const TetMesh& m, const double* x, int t,
                          const std::vector<char>* blocked, int max_steps) {
  LocateResult r;
  r.tet = t;
  unsigned rot = static_cast<unsigned>(t) * 2654435761u;
  for (int step = 0; step < max_steps && t >= 0; ++step) {
    const int* tv = &m.tets[4 * t];
    int next = -1;
    // Rotate the face order so that the walk cannot cycle on degenerate configurations.
    rot = rot * 1103515245u + 12345u;
    const int first = static_cast<int>((rot >> 16) & 3u);
    for (int i = 0; i < 4 && next < 0; ++i) {
      const int f = (first + i) & 3;
      const double* a = m.point(tv[kTetFace[f][0]]);
      const double* b = m.point(tv[kTetFace[f][1]]);
      const double* c = m.point(tv[kTetFace[f][2]]);
      // Faces are oriented outwards: x strictly beyond face f means orient3d(a,b,c,x) > 0.
      if (orient3d(a, b, c, x) > 0) {
        const int o = m.adj[4 * t + f];
        if (o < 0 || (blocked && (*blocked)[4 * t + f])) {
          r.status = LocateStatus::kBlocked;
          r.tet = t;
          return r;
        }
        next = o / 4;
      }
    }
    if (next < 0) {
      r.status = LocateStatus::kInside;
      r.tet = t;
      return r;
    }
    t = next;
  }
  r.status = LocateStatus::kBlocked;
  r.tet = t;
  return r;
}

void barycentric(const TetMesh& m, int t, const double* x, double w[4]) {
  const int* v = &m.tets[4 * t];
  const double* p[4] = {m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])};
  const double vol = tet_volume(p[0], p[1], p[2], p[3]);
  if (vol == 0) {
    w[0] = w[1] = w[2] = w[3] = 0.25;
    return;
  }
  w[0] = tet_volume(x, p[1], p[2], p[3]) / vol;
  w[1] = tet_volume(p[0], x, p[2], p[3]) / vol;
  w[2] = tet_volume(p[0], p[1], x, p[3]) / vol;
  w[3] = 1.0 - w[0] - w[1] - w[2];
}

}  // namespace cvtmesh
