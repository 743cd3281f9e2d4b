#include "core/smoothing/smooth_laplacian.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/geometry/predicates.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {
namespace {

double quality_of(const TetMesh& mesh, int t, Measure m) {
  const int* v = &mesh.tets[4 * static_cast<std::size_t>(t)];
  return tet_quality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]), m);
}

}  // namespace

SmoothStats smooth_laplacian(TetMesh& mesh, const SmoothOptions& options) {
  if (options.measure == Measure::kMaxAngle)
    throw std::invalid_argument("smooth_laplacian: measure 'max-angle' is not larger-is-better");
  if (options.passes < 0) throw std::invalid_argument("smooth_laplacian: passes must be >= 0");
  const int nv = mesh.nb_vertices(), nt = mesh.nb_tets();
  const VertexTets star = vertex_tets(mesh);
  std::vector<double> q(static_cast<std::size_t>(nt), std::numeric_limits<double>::infinity());
  for (int t = 0; t < nt; ++t)
    if (mesh.tets[4 * static_cast<std::size_t>(t)] >= 0)
      q[t] = quality_of(mesh, t, options.measure);
  SmoothStats stats;
  stats.min_before = nt ? *std::min_element(q.begin(), q.end()) : 0;

  std::vector<int> nbrs;
  std::vector<double> new_q;
  for (int pass = 0; pass < options.passes; ++pass) {
    ++stats.passes;
    for (int v = 0; v < nv; ++v) {
      if (mesh.vclass[v].dim < 3 || star.nb_tets_of(v) == 0) continue;
      // The adjacent vertices: the other vertices of the star.
      nbrs.clear();
      double old_min = std::numeric_limits<double>::infinity();
      for (const int* t = star.begin_of(v); t != star.end_of(v); ++t) {
        old_min = std::min(old_min, q[*t]);
        for (int k = 0; k < 4; ++k) {
          const int w = mesh.tets[4 * static_cast<std::size_t>(*t) + k];
          if (w != v) nbrs.push_back(w);
        }
      }
      std::sort(nbrs.begin(), nbrs.end());
      nbrs.erase(std::unique(nbrs.begin(), nbrs.end()), nbrs.end());
      double target[3] = {0, 0, 0};
      for (int w : nbrs)
        for (int k = 0; k < 3; ++k) target[k] += mesh.point(w)[k];
      for (int k = 0; k < 3; ++k) target[k] /= static_cast<double>(nbrs.size());

      double* P = mesh.point(v);
      const double orig[3] = {P[0], P[1], P[2]};
      bool moved = false;
      for (int attempt = 0; attempt < (options.half_step ? 2 : 1) && !moved; ++attempt) {
        const double s = attempt == 0 ? 1.0 : 0.5;
        for (int k = 0; k < 3; ++k) P[k] = orig[k] + s * (target[k] - orig[k]);
        new_q.clear();
        bool ok = true;
        double new_min = std::numeric_limits<double>::infinity();
        for (const int* t = star.begin_of(v); t != star.end_of(v) && ok; ++t) {
          const int* tv = &mesh.tets[4 * static_cast<std::size_t>(*t)];
          if (orient3d(mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]),
                       mesh.point(tv[3])) <= 0) {
            ok = false;
            break;
          }
          new_q.push_back(quality_of(mesh, *t, options.measure));
          new_min = std::min(new_min, new_q.back());
        }
        if (ok && new_min >= old_min) {
          moved = true;
          std::size_t i = 0;
          for (const int* t = star.begin_of(v); t != star.end_of(v); ++t) q[*t] = new_q[i++];
          ++(attempt == 0 ? stats.nb_moved : stats.nb_half);
        }
      }
      if (!moved) {
        for (int k = 0; k < 3; ++k) P[k] = orig[k];
        ++stats.nb_rejected;
      }
    }
  }
  stats.min_after = nt ? *std::min_element(q.begin(), q.end()) : 0;
  return stats;
}

}  // namespace cvtmesh
