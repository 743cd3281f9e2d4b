#include "core/boundary/boundary_hausdorff.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

bool surface_flip_within(const TetMesh& m, const BoundaryModel& model, const BoundaryFans& fans,
                         int f1, int f2, int a, int b, int c, int d, double tolerance) {
  if (!std::isfinite(tolerance)) return true;
  for (int apex : {a, b}) {
    double pts[10][3];
    triangle_samples(m.point(apex), m.point(c), m.point(d), pts);
    for (int i = 3; i < 10; ++i)
      if (!model.geometry->within_distance(pts[i], tolerance)) return false;
  }
  for (int x : {a, b, c, d}) {
    if (model.input_xyz.size() < 3 * static_cast<std::size_t>(x) + 3) continue;
    const double* p0 = &model.input_xyz[3 * static_cast<std::size_t>(x)];
    double dist = std::numeric_limits<double>::infinity();
    for (const int* f = fans.begin_of(x); f != fans.end_of(x); ++f) {
      if (*f == f1 || *f == f2) continue;
      const int* w = &m.tris[3 * static_cast<std::size_t>(*f)];
      dist =
          std::min(dist, point_triangle_distance(p0, m.point(w[0]), m.point(w[1]), m.point(w[2])));
    }
    for (int apex : {a, b})
      if (x == apex || x == c || x == d)
        dist = std::min(dist, point_triangle_distance(p0, m.point(apex), m.point(c), m.point(d)));
    if (dist > tolerance) return false;
  }
  return true;
}

}  // namespace cvtmesh
