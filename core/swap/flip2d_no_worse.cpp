#include "core/swap/flip2d_no_worse.h"

#include <algorithm>

#include "core/quality/quality.h"
#include "core/swap/flip2d.h"

namespace cvtmesh {

bool flip2d_no_worse(const TriMesh2& mesh, int slot) {
  if (!flip2d_possible(mesh, slot)) return false;
  const int o = mesh.adj[slot];
  const int t = slot / 3, e = slot % 3;
  const int* tv = &mesh.tris[3 * t];
  const double* c = mesh.point(tv[e]);
  const double* a = mesh.point(tv[(e + 1) % 3]);
  const double* b = mesh.point(tv[(e + 2) % 3]);
  const double* d = mesh.point(mesh.tris[o]);
  auto q = [](const double* x, const double* y, const double* z, Measure m) {
    return tri_quality(x, y, z, 2, m);
  };
  const double q1 = q(c, a, b, Measure::kQ), q2 = q(d, b, a, Measure::kQ);
  const double n1 = q(c, a, d, Measure::kQ), n2 = q(d, b, c, Measure::kQ);
  const double qmin_before = std::min(q1, q2), qmin_after = std::min(n1, n2);
  if (qmin_after < qmin_before) return false;
  const double amin_before =
      std::min(q(c, a, b, Measure::kMinAngle), q(d, b, a, Measure::kMinAngle));
  const double amin_after =
      std::min(q(c, a, d, Measure::kMinAngle), q(d, b, c, Measure::kMinAngle));
  if (amin_after < amin_before) return false;
  const double amax_before =
      std::max(q(c, a, b, Measure::kMaxAngle), q(d, b, a, Measure::kMaxAngle));
  const double amax_after =
      std::max(q(c, a, d, Measure::kMaxAngle), q(d, b, c, Measure::kMaxAngle));
  if (amax_after > amax_before) return false;
  return qmin_after > qmin_before + 1e-9 || n1 + n2 > (q1 + q2) * (1 + 1e-12) + 1e-12;
}

}  // namespace cvtmesh
