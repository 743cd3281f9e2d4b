#include "core/cvt/move_safeguard3.h"

#include "core/mesh/locate_point.h"

namespace cvtmesh {

bool safe_target3(const TetMesh& m, const CellMesh& cm, int v, const double* goal, int max_halvings,
                  double* out) {
  const double* z = m.point(v);
  const VertexStar& star = cm.star;
  double t = 1.0;
  for (int h = 0; h <= max_halvings; ++h, t *= 0.5) {
    double x[3];
    for (int d = 0; d < 3; ++d) x[d] = z[d] + t * (goal[d] - z[d]);
    const LocateResult r = locate_point(m, x, star.tets[star.offset[v]], &cm.constrained, 100000);
    if (r.status == LocateStatus::kInside) {
      for (int d = 0; d < 3; ++d) out[d] = x[d];
      return h == 0;
    }
  }
  for (int d = 0; d < 3; ++d) out[d] = z[d];
  return false;
}

int safe_targets3(const TetMesh& m, const CellMesh& cm, const std::vector<int>& free_ids,
                  const std::vector<double>& goal, int max_halvings, std::vector<double>& out) {
  const int nf = static_cast<int>(free_ids.size());
  out.resize(goal.size());
  int nb_limited = 0;
#pragma omp parallel for schedule(static, 256) reduction(+ : nb_limited)
  for (int i = 0; i < nf; ++i)
    if (!safe_target3(m, cm, free_ids[i], &goal[3 * i], max_halvings, &out[3 * i])) ++nb_limited;
  return nb_limited;
}

}  // namespace cvtmesh
