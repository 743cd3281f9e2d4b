#include "core/boundary/boundary_fans.h"

namespace cvtmesh {

BoundaryFans boundary_fans(const TetMesh& m) {
  BoundaryFans f;
  const int nv = m.nb_vertices(), nf = m.nb_tris();
  f.offset.assign(static_cast<std::size_t>(nv) + 1, 0);
  for (int t = 0; t < nf; ++t)
    for (int k = 0; k < 3; ++k) ++f.offset[m.tris[3 * t + k] + 1];
  for (int v = 0; v < nv; ++v) f.offset[v + 1] += f.offset[v];
  f.tris.resize(static_cast<std::size_t>(f.offset[nv]));
  std::vector<int> fill(f.offset.begin(), f.offset.end() - 1);
  for (int t = 0; t < nf; ++t)
    for (int k = 0; k < 3; ++k) f.tris[fill[m.tris[3 * t + k]]++] = t;
  return f;
}

Vec3 fan_normal(const TetMesh& m, const BoundaryFans& fans, int v) {
  Vec3 sum{0, 0, 0}, first{0, 0, 0};
  bool have_first = false;
  for (const int* t = fans.begin_of(v); t != fans.end_of(v); ++t) {
    const int* w = &m.tris[3 * static_cast<std::size_t>(*t)];
    Vec3 n = cross(sub(m.point(w[1]), m.point(w[0])), sub(m.point(w[2]), m.point(w[0])));
    if (!have_first) {
      first = n;
      have_first = true;
    } else if (dot(n, first) < 0) {
      n = -1.0 * n;
    }
    sum = sum + n;
  }
  const double l = norm(sum);
  return l > 0 ? (1 / l) * sum : Vec3{0, 0, 0};
}

}  // namespace cvtmesh
