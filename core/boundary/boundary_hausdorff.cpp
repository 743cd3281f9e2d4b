#include "core/boundary/boundary_hausdorff.h"

#include <algorithm>

#include "core/boundary/triangle_set_distance.h"

namespace cvtmesh {

void triangle_samples(const double* a, const double* b, const double* c, double out[10][3]) {
  static const double w[10][3] = {{1, 0, 0},
                                  {0, 1, 0},
                                  {0, 0, 1},
                                  {1.0 / 3, 1.0 / 3, 1.0 / 3},
                                  {0.5, 0.5, 0},
                                  {0, 0.5, 0.5},
                                  {0.5, 0, 0.5},
                                  {2.0 / 3, 1.0 / 6, 1.0 / 6},
                                  {1.0 / 6, 2.0 / 3, 1.0 / 6},
                                  {1.0 / 6, 1.0 / 6, 2.0 / 3}};
  for (int i = 0; i < 10; ++i)
    for (int d = 0; d < 3; ++d) out[i][d] = w[i][0] * a[d] + w[i][1] * b[d] + w[i][2] * c[d];
}

HausdorffDistance boundary_hausdorff(const TetMesh& m, const BoundaryGeometry& g) {
  HausdorffDistance h;
  const int nf = m.nb_tris();
  double to_reference = 0, from_reference = 0;
#pragma omp parallel for schedule(dynamic, 64) reduction(max : to_reference) if (g.thread_safe())
  for (int f = 0; f < nf; ++f) {
    double s[10][3];
    const int* v = &m.tris[3 * static_cast<std::size_t>(f)];
    triangle_samples(m.point(v[0]), m.point(v[1]), m.point(v[2]), s);
    for (const auto& p : s) to_reference = std::max(to_reference, g.distance_to_boundary(p));
  }
  const std::vector<double> ref = g.samples();
  if (!ref.empty()) {
    const TriangleSetDistance now(m.xyz, m.tris);
    const long ns = static_cast<long>(ref.size() / 3);
#pragma omp parallel for schedule(static) reduction(max : from_reference)
    for (long i = 0; i < ns; ++i)
      from_reference = std::max(from_reference, now.distance(&ref[3 * i]));
  }
  h.to_reference = to_reference;
  h.from_reference = from_reference;
  return h;
}

}  // namespace cvtmesh
