#include "core/boundary/flip_surface_edges.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/boundary_hausdorff.h"
#include "core/boundary/surface_folds.h"
#include "core/geometry/predicates.h"
#include "core/geometry/tet_geometry.h"
#include "core/geometry/vec3.h"
#include "core/mesh/face_key.h"
#include "core/quality/quality.h"

namespace cvtmesh {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180;

double min_angle(const double* a, const double* b, const double* c) {
  const auto ang = tri_angles(a, b, c, 3);
  return std::min({ang[0], ang[1], ang[2]});
}

int third(const int* t, int a, int b) {
  for (int k = 0; k < 3; ++k)
    if (t[k] != a && t[k] != b) return t[k];
  return -1;
}

bool runs(const int* t, int a, int b) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == a) return t[(k + 1) % 3] == b;
  return false;
}

struct EdgeTris {
  int f[2] = {-1, -1};
  int count = 0;
};

}  // namespace

SurfaceFlipStats flip_surface_edges(TetMesh& m, const BoundaryModel& model,
                                    const SurfaceFlipOptions& o) {
  SurfaceFlipStats st;
  const double cos_flat = std::cos(o.flat_angle * kDegree);
  const int nf = m.nb_tris();
  for (int pass = 0; pass < o.passes; ++pass) {
    ++st.passes;
    const BoundaryFans fans = boundary_fans(m);
    std::unordered_map<EdgeKey, EdgeTris, EdgeKeyHash> edges;
    edges.reserve(3 * static_cast<std::size_t>(nf));
    for (int f = 0; f < nf; ++f) {
      const int* t = &m.tris[3 * f];
      if (t[0] < 0) continue;
      for (int k = 0; k < 3; ++k) {
        EdgeTris& e = edges[edge_key(t[k], t[(k + 1) % 3])];
        if (e.count < 2) e.f[e.count] = f;
        ++e.count;
      }
    }
    // Edges in a fixed order (the map's is not), so that the result does not depend on it.
    std::vector<EdgeKey> order;
    order.reserve(edges.size());
    for (const auto& [k, e] : edges)
      if (e.count == 2) order.push_back(k);
    std::sort(order.begin(), order.end());
    std::vector<char> touched(static_cast<std::size_t>(m.nb_vertices()), 0);
    long flipped = 0;
    for (const EdgeKey& key : order) {
      const int a = key[0], b = key[1];
      const EdgeTris& e = edges.at(key);
      const int f1 = e.f[0], f2 = e.f[1];
      if (m.tri_surface[f1] != m.tri_surface[f2]) continue;
      const int* t1 = &m.tris[3 * f1];
      const int* t2 = &m.tris[3 * f2];
      const int c = third(t1, a, b), d = third(t2, a, b);
      if (c < 0 || d < 0 || c == d) continue;
      if (touched[a] || touched[b] || touched[c] || touched[d]) continue;
      if (model.may_be_curve_edge(a, b)) continue;
      if (std::binary_search(o.kept_edges.begin(), o.kept_edges.end(), std::array<int, 2>{a, b}))
        continue;
      if (edges.count(edge_key(c, d))) continue;
      const double *pa = m.point(a), *pb = m.point(b), *pc = m.point(c), *pd = m.point(d);
      // The Delaunay (max-min angle) criterion first: the cheapest refusal.
      const double before = std::min(min_angle(pa, pb, pc), min_angle(pa, pb, pd));
      const double after = std::min(min_angle(pa, pc, pd), min_angle(pb, pd, pc));
      if (!(after > before + o.min_gain)) continue;
      auto max_angle = [](const double* x, const double* y, const double* z) {
        return tri_quality(x, y, z, 3, Measure::kMaxAngle);
      };
      auto q = [](const double* x, const double* y, const double* z) {
        return tri_quality(x, y, z, 3, Measure::kQ);
      };
      const double max_before = std::max(max_angle(pa, pb, pc), max_angle(pa, pb, pd));
      const double max_after = std::max(max_angle(pa, pc, pd), max_angle(pb, pd, pc));
      if (max_after > std::max(max_before, o.max_angle_ceiling)) continue;
      if (std::min(q(pa, pc, pd), q(pb, pd, pc)) < std::min(q(pa, pb, pc), q(pa, pb, pd))) continue;
      ++st.nb_tried;
      // The pair's normal, oriented as f1 (f2's reversed if it runs a -> b as f1 does).
      Vec3 n1 = cross(sub(m.point(t1[1]), m.point(t1[0])), sub(m.point(t1[2]), m.point(t1[0])));
      Vec3 n2 = cross(sub(m.point(t2[1]), m.point(t2[0])), sub(m.point(t2[2]), m.point(t2[0])));
      if (runs(t1, a, b) == runs(t2, a, b)) n2 = -1.0 * n2;
      const double l1 = norm(n1), l2 = norm(n2);
      if (!(l1 > 0 && l2 > 0)) continue;
      if (o.coplanar_only) {
        if (orient3d(pa, pb, pc, pd) != 0) continue;
      } else if (dot(n1, n2) < cos_flat * l1 * l2) {
        continue;
      }
      // The new triangles turn as f1 did, seen from a point on the pair's normal (exact).
      const Vec3 n = (1 / l1) * n1 + (1 / l2) * n2;
      const double len = std::sqrt(std::max(dist2(pa, pb), dist2(pc, pd)));
      const double nn = norm(n);
      if (!(nn > 0)) continue;
      double eye[3];
      for (int k = 0; k < 3; ++k) eye[k] = (pa[k] + pb[k] + pc[k] + pd[k]) / 4 + len * n[k] / nn;
      const double s1 = orient3d(m.point(t1[0]), m.point(t1[1]), m.point(t1[2]), eye);
      const std::array<int, 6> nt = flipped_triangles(m, f1, a, b, c, d);
      const double s_new1 = orient3d(m.point(nt[0]), m.point(nt[1]), m.point(nt[2]), eye);
      const double s_new2 = orient3d(m.point(nt[3]), m.point(nt[4]), m.point(nt[5]), eye);
      if (s1 == 0 || s_new1 == 0 || s_new2 == 0 || (s1 > 0) != (s_new1 > 0) ||
          (s1 > 0) != (s_new2 > 0))
        continue;
      if (flip_folds_surface(m, fans, f1, f2, a, b, c, d, cos_flat)) continue;
      if (!o.coplanar_only && std::isfinite(o.hausdorff) &&
          !surface_flip_within(m, model, fans, f1, f2, a, b, c, d, o.hausdorff))
        continue;
      retarget_flipped_triangles(m, f1, f2, a, b, c, d);
      touched[a] = touched[b] = touched[c] = touched[d] = 1;
      ++flipped;
    }
    st.nb_flipped += flipped;
    if (!flipped) break;
  }
  return st;
}

}  // namespace cvtmesh
