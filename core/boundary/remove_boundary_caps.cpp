#include "core/boundary/remove_boundary_caps.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/boundary/boundary_hausdorff.h"
#include "core/boundary/surface_folds.h"
#include "core/geometry/tet_geometry.h"
#include "core/geometry/vec3.h"
#include "core/mesh/build_adjacency.h"
#include "core/quality/quality.h"
#include "core/swap/compact_tets.h"

namespace cvtmesh {
namespace {

constexpr double kPi = 3.14159265358979323846;

double tet_objective(const TetMesh& m, int t) {
  const int* w = &m.tets[4 * static_cast<std::size_t>(t)];
  const double *a = m.point(w[0]), *b = m.point(w[1]), *c = m.point(w[2]), *d = m.point(w[3]);
  return std::min(tet_quality(a, b, c, d, Measure::kQ),
                  tet_quality(a, b, c, d, Measure::kMinAngle) / 60);
}

double tri_q(const TetMesh& m, int a, int b, int c) {
  return tri_quality(m.point(a), m.point(b), m.point(c), 3, Measure::kQ);
}

// The boundary triangle with vertices {x, y, z} (from x's fan), or -1.
int boundary_triangle(const TetMesh& m, const BoundaryFans& fans, int x, int y, int z) {
  for (const int* f = fans.begin_of(x); f != fans.end_of(x); ++f) {
    const int* w = &m.tris[3 * static_cast<std::size_t>(*f)];
    const bool has_y = w[0] == y || w[1] == y || w[2] == y;
    const bool has_z = w[0] == z || w[1] == z || w[2] == z;
    if (has_y && has_z) return *f;
  }
  return -1;
}

bool has_boundary_edge(const TetMesh& m, const BoundaryFans& fans, int x, int y) {
  for (const int* f = fans.begin_of(x); f != fans.end_of(x); ++f) {
    const int* w = &m.tris[3 * static_cast<std::size_t>(*f)];
    if (w[0] == y || w[1] == y || w[2] == y) return true;
  }
  return false;
}

}  // namespace

CapCheck plan_cap_removal(const TetMesh& m, const BoundaryModel& model, const VertexTets& star,
                          const BoundaryFans& fans, int t, const CapRemovalOptions& o, CapPlan& p) {
  (void)star;
  const int* w = &m.tets[4 * static_cast<std::size_t>(t)];
  // The boundary faces of t (face k is opposite vertex k).
  int faces[4], nb = 0;
  for (int k = 0; k < 4; ++k) {
    faces[k] = boundary_triangle(m, fans, w[kTetFace[k][0]], w[kTetFace[k][1]], w[kTetFace[k][2]]);
    nb += faces[k] >= 0;
  }
  if (nb != 2) return CapCheck::kNotACap;
  // c, d: the vertices opposite the boundary faces; (a, b) their common edge.
  int kc = -1, kd = -1;
  for (int k = 0; k < 4; ++k)
    if (faces[k] < 0) (kc < 0 ? kc : kd) = k;
  // faces[kc] < 0 means the face opposite w[kc] is interior: then w[kc] lies on both boundary
  // faces, i.e. it is a or b.
  p = CapPlan{};
  p.tet = t;
  p.a = w[kc];
  p.b = w[kd];
  int others[2], n = 0;
  for (int k = 0; k < 4; ++k)
    if (k != kc && k != kd) others[n++] = k;
  // The boundary face opposite others[0] holds a, b and the other one: that one is c.
  p.f1 = faces[others[1]];  // opposite d = w[others[1]]: the face (a, b, c)
  p.f2 = faces[others[0]];  // (a, b, d)
  p.c = w[others[0]];
  p.d = w[others[1]];
  const int a = p.a, b = p.b, c = p.c, d = p.d;
  if (m.tri_surface[p.f1] != m.tri_surface[p.f2]) return CapCheck::kNotACap;
  // On the domain's boundary (not an interface between two regions).
  for (int i = 0; i < 2; ++i)
    if (m.adj[4 * static_cast<std::size_t>(t) + others[i]] >= 0) return CapCheck::kNotACap;
  // The neighbours across the interior faces (opposite a: (b, c, d); opposite b: (a, c, d)).
  int nbr[2];
  for (int i = 0; i < 2; ++i) {
    const int k = i == 0 ? kc : kd;
    const int link = m.adj[4 * static_cast<std::size_t>(t) + k];
    if (link < 0) return CapCheck::kNotACap;
    nbr[i] = link / 4;
    if (m.tet_region[nbr[i]] != m.tet_region[t]) return CapCheck::kNotACap;
  }
  if (model.may_be_curve_edge(a, b)) return CapCheck::kCurve;
  // Flat enough: the normals of (a, b, c) and (b, a, d) (consistent along (a, b)).
  const Vec3 n1 = cross(sub(m.point(b), m.point(a)), sub(m.point(c), m.point(a)));
  const Vec3 n2 = cross(sub(m.point(a), m.point(b)), sub(m.point(d), m.point(b)));
  const double l1 = norm(n1), l2 = norm(n2);
  if (!(l1 > 0 && l2 > 0) || dot(n1, n2) < std::cos(o.flat_angle * kPi / 180) * l1 * l2)
    return CapCheck::kNotFlat;
  if (has_boundary_edge(m, fans, c, d)) return CapCheck::kNonManifold;
  // The local minimum, before and after (the neighbours are unchanged but bound it both times).
  const double nbr_min = std::min(tet_objective(m, nbr[0]), tet_objective(m, nbr[1]));
  p.old_min = std::min({tet_objective(m, t), tri_q(m, a, b, c), tri_q(m, a, b, d), nbr_min});
  p.new_min = std::min({tri_q(m, a, c, d), tri_q(m, b, c, d), nbr_min});
  if (p.new_min <= p.old_min + o.min_gain) return CapCheck::kNoGain;
  if (!surface_flip_within(m, model, fans, p.f1, p.f2, a, b, c, d, o.hausdorff))
    return CapCheck::kHausdorff;
  if (flip_folds_surface(m, fans, p.f1, p.f2, a, b, c, d, std::cos(o.flat_angle * kPi / 180)))
    return CapCheck::kFolds;
  if (o.volume_budget) {
    const VolumeBudget& vb = *o.volume_budget;
    const double dv = -tet_volume(m.point(w[0]), m.point(w[1]), m.point(w[2]), m.point(w[3]));
    p.delta.assign(vb.region.size(), 0);
    for (std::size_t i = 0; i < vb.region.size(); ++i)
      if (vb.region[i] == m.tet_region[t]) {
        p.delta[i] = dv;
        if (std::fabs(vb.change[i] + dv) > vb.tolerance * std::fabs(vb.volume[i]))
          return CapCheck::kVolume;
      }
  }
  return CapCheck::kOk;
}

void apply_cap_removal(TetMesh& m, const CapPlan& p, VolumeBudget* budget) {
  if (budget && !p.delta.empty()) budget->commit(p.delta);
  // The tets behind its two inner faces now stand on the boundary.
  if (m.adj.size() == m.tets.size())
    for (int f = 0; f < 4; ++f) {
      int& here = m.adj[4 * static_cast<std::size_t>(p.tet) + f];
      if (here >= 0) m.adj[here] = -1;
      here = -1;
    }
  m.tets[4 * static_cast<std::size_t>(p.tet)] = -1;
  retarget_flipped_triangles(m, p.f1, p.f2, p.a, p.b, p.c, p.d);
}

CapRemovalStats remove_boundary_caps(TetMesh& mesh, const BoundaryModel& model,
                                     const CapRemovalOptions& o) {
  CapRemovalStats stats;
  if (!model.geometry) return stats;
  if (mesh.adj.size() != mesh.tets.size()) build_adjacency(mesh);
  bool changed = false;
  for (int pass = 0; pass < o.passes; ++pass) {
    ++stats.passes;
    const VertexTets star = vertex_tets(mesh);
    const BoundaryFans fans = boundary_fans(mesh);
    // Candidates: tets with four boundary vertices (each on a boundary triangle), worst first.
    std::vector<std::pair<double, int>> caps;
    for (int t = 0; t < mesh.nb_tets(); ++t) {
      const int* w = &mesh.tets[4 * static_cast<std::size_t>(t)];
      if (w[0] < 0) continue;
      bool on_boundary = true;
      for (int k = 0; k < 4; ++k) on_boundary &= fans.end_of(w[k]) != fans.begin_of(w[k]);
      if (!on_boundary) continue;
      const double q = tet_objective(mesh, t);
      if (q < o.cap_below) caps.push_back({q, t});
    }
    std::sort(caps.begin(), caps.end());
    std::vector<char> dirty(static_cast<std::size_t>(mesh.nb_vertices()), 0);
    long removed = 0;
    for (const auto& [q, t] : caps) {
      const int* w = &mesh.tets[4 * static_cast<std::size_t>(t)];
      bool stale = false;
      for (int k = 0; k < 4; ++k) stale |= dirty[w[k]] != 0;
      if (stale) continue;
      ++stats.nb_tried;
      CapPlan plan;
      if (plan_cap_removal(mesh, model, star, fans, t, o, plan) != CapCheck::kOk) continue;
      for (int k = 0; k < 4; ++k) dirty[w[k]] = 1;  // stale stars and fans: not again this pass
      apply_cap_removal(mesh, plan, o.volume_budget);
      ++removed;
      ++stats.nb_removed;
    }
    if (removed == 0) break;
    compact_tets(mesh);
    changed = true;
  }
  if (changed && mesh.adj.size() != mesh.tets.size()) build_adjacency(mesh);
  return stats;
}

}  // namespace cvtmesh
