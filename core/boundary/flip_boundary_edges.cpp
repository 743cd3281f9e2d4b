#include "core/boundary/flip_boundary_edges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/boundary_hausdorff.h"
#include "core/boundary/boundary_move.h"
#include "core/boundary/surface_folds.h"
#include "core/boundary/triangle_set_distance.h"
#include "core/geometry/predicates.h"
#include "core/geometry/tet_geometry.h"
#include "core/geometry/vec3.h"
#include "core/mesh/build_adjacency.h"
#include "core/mesh/vertex_tets.h"
#include "core/quality/quality.h"
#include "core/swap/apply_swap.h"
#include "core/swap/compact_tets.h"
#include "core/swap/polygon_triangulations.h"

namespace cvtmesh {
namespace {

constexpr double kPi = 3.14159265358979323846;

double tet_objective(const double* a, const double* b, const double* c, const double* d) {
  return std::min(tet_quality(a, b, c, d, Measure::kQ),
                  tet_quality(a, b, c, d, Measure::kMinAngle) / 60);
}

double tri_q(const TetMesh& m, int a, int b, int c) {
  return tri_quality(m.point(a), m.point(b), m.point(c), 3, Measure::kQ);
}

Vec3 normal_of(const TetMesh& m, int a, int b, int c) {
  return cross(sub(m.point(b), m.point(a)), sub(m.point(c), m.point(a)));
}

// The planned flip of boundary edge (a, b).
struct FlipPlan {
  int f1 = -1, f2 = -1, c = -1, d = -1, region = 0;
  std::vector<int> ring;                 // old tets
  std::vector<std::array<int, 4>> tets;  // new tets
  std::vector<double> delta;             // volume change per budget region
};

}  // namespace

BoundaryFlipStats flip_boundary_edges(TetMesh& mesh, const BoundaryModel& model,
                                      const BoundaryFlipOptions& o) {
  BoundaryFlipStats stats;
  if (!model.geometry) return stats;
  const double cos_flat = std::cos(o.flat_angle * kPi / 180);
  bool changed_any = false;
  if (mesh.adj.size() != mesh.tets.size()) build_adjacency(mesh);
  for (int pass = 0; pass < o.passes; ++pass) {
    ++stats.passes;
    const VertexTets star = vertex_tets(mesh);
    const BoundaryFans fans = boundary_fans(mesh);
    std::vector<char> dirty(static_cast<std::size_t>(mesh.nb_vertices()), 0);
    // Candidate edges: of the poor boundary triangles, worst first.
    std::vector<std::pair<double, std::array<int, 2>>> edges;
    for (int f = 0; f < mesh.nb_tris(); ++f) {
      const int* v = &mesh.tris[3 * static_cast<std::size_t>(f)];
      const double q = tri_q(mesh, v[0], v[1], v[2]);
      if (q >= o.tri_below) continue;
      for (int k = 0; k < 3; ++k)
        edges.push_back({q, {std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3])}});
    }
    std::sort(edges.begin(), edges.end());
    long flipped = 0;
    for (const auto& [unused, e] : edges) {
      const int a = e[0], b = e[1];
      if (dirty[a] || dirty[b]) continue;
      if (!model.movable(a) && !model.movable(b)) continue;
      if (model.may_be_curve_edge(a, b)) continue;
      ++stats.nb_tried;
      FlipPlan p;
      for (const int* f = fans.begin_of(a); f != fans.end_of(a); ++f) {
        const int* w = &mesh.tris[3 * static_cast<std::size_t>(*f)];
        if (w[0] != b && w[1] != b && w[2] != b) continue;
        const int third = w[0] != a && w[0] != b ? w[0] : (w[1] != a && w[1] != b ? w[1] : w[2]);
        if (p.f1 < 0) {
          p.f1 = *f;
          p.c = third;
        } else if (p.f2 < 0) {
          p.f2 = *f;
          p.d = third;
        } else {
          p.f2 = -2;  // more than two triangles at the edge
        }
      }
      if (p.f1 < 0 || p.f2 < 0 || mesh.tri_surface[p.f1] != mesh.tri_surface[p.f2]) continue;
      const int c = p.c, d = p.d;
      if (dirty[c] || dirty[d]) continue;
      // Flat enough: normals oriented consistently (opposite directions along (a, b)).
      Vec3 n1 = normal_of(mesh, a, b, c), n2 = normal_of(mesh, b, a, d);
      const double l1 = norm(n1), l2 = norm(n2);
      if (!(l1 > 0 && l2 > 0) || dot(n1, n2) < cos_flat * l1 * l2) continue;
      // (c, d) must not be an edge already.
      bool exists = false;
      for (const int* t = star.begin_of(c); t != star.end_of(c) && !exists; ++t)
        for (int k = 0; k < 4; ++k) exists |= mesh.tets[4 * static_cast<std::size_t>(*t) + k] == d;
      if (exists) continue;
      // The ring around (a, b), one region, ordered from c to d.
      std::vector<std::array<int, 2>> links;
      bool ok = true;
      for (const int* t = star.begin_of(a); t != star.end_of(a); ++t) {
        const int* w = &mesh.tets[4 * static_cast<std::size_t>(*t)];
        if (w[0] != b && w[1] != b && w[2] != b && w[3] != b) continue;
        if (p.ring.empty()) p.region = mesh.tet_region[*t];
        ok &= mesh.tet_region[*t] == p.region;
        p.ring.push_back(*t);
        std::array<int, 2> xy{-1, -1};
        int n = 0;
        for (int k = 0; k < 4; ++k)
          if (w[k] != a && w[k] != b) xy[n++] = w[k];
        links.push_back(xy);
      }
      const int k = static_cast<int>(p.ring.size());
      if (!ok || k < 1 || k > 6) continue;
      std::vector<int> chain = {c};
      std::vector<char> used(links.size(), 0);
      for (int step = 0; step < k; ++step) {
        int next = -1;
        for (int i = 0; i < k && next < 0; ++i)
          if (!used[i] && (links[i][0] == chain.back() || links[i][1] == chain.back())) {
            used[i] = 1;
            next = links[i][0] == chain.back() ? links[i][1] : links[i][0];
          }
        if (next < 0) break;
        chain.push_back(next);
      }
      if (static_cast<int>(chain.size()) != k + 1 || chain.back() != d) continue;
      if (k == 1) continue;  // a lone tet: the flip would remove it (not a retriangulation)
      // Old minimum: the ring tets and the two triangles.
      double old_min = std::min(tri_q(mesh, a, b, c), tri_q(mesh, a, b, d));
      for (int t : p.ring) {
        const int* w = &mesh.tets[4 * static_cast<std::size_t>(t)];
        old_min = std::min(old_min, tet_objective(mesh.point(w[0]), mesh.point(w[1]),
                                                  mesh.point(w[2]), mesh.point(w[3])));
      }
      double best = std::min(tri_q(mesh, a, c, d), tri_q(mesh, b, c, d));
      if (best <= old_min + o.min_gain) continue;
      // The ring's turning sense: the old tet on the first link stands on b's side of the face
      // (a, chain[0], chain[1]), so every new tet coned to a must stand there too. With the
      // polygon's triangles in chain order, a must then see every one of them from the same
      // side (-s), and b from the other: a sign chosen per triangle lets each tet be positive
      // while the cone folds over itself (igl_bunny: two tets on the same side of a face).
      const double s0 =
          orient3d(mesh.point(a), mesh.point(chain[0]), mesh.point(chain[1]), mesh.point(b));
      if (s0 == 0) continue;
      const int sign_a = s0 > 0 ? -1 : 1;
      // The best triangulation of the polygon chain[0..k] coned to a and b.
      const PolygonTriangulations& table = polygon_triangulations(k + 1);
      double best_min = -1;
      std::vector<std::array<int, 4>> best_tets;
      for (const auto& tri_ids : table.triangulations) {
        std::vector<std::array<int, 4>> tets;
        double mn = best;
        bool valid = true;
        for (int id : tri_ids) {
          const auto& tr = table.triangles[id];
          const int u = chain[tr[0]], v = chain[tr[1]], w = chain[tr[2]];
          // a and b strictly on both sides of the polygon triangle, a on the ring's side.
          const double sa = orient3d(mesh.point(u), mesh.point(v), mesh.point(w), mesh.point(a));
          const double sb = orient3d(mesh.point(u), mesh.point(v), mesh.point(w), mesh.point(b));
          if (!(sign_a * sa > 0 && sign_a * sb < 0)) {
            valid = false;
            break;
          }
          // A diagonal of the polygon must not be an edge of the mesh already.
          for (int i = 0; i < 3 && valid; ++i) {
            const int x = tr[i], y = tr[(i + 1) % 3];
            if (std::abs(x - y) == 1 || std::abs(x - y) == k) continue;  // a side
            for (const int* t = star.begin_of(chain[x]); t != star.end_of(chain[x]) && valid; ++t)
              for (int j = 0; j < 4; ++j)
                if (mesh.tets[4 * static_cast<std::size_t>(*t) + j] == chain[y]) valid = false;
          }
          if (!valid) break;
          for (int apex : {a, b}) {
            std::array<int, 4> t{u, v, w, apex};
            if (orient3d(mesh.point(u), mesh.point(v), mesh.point(w), mesh.point(apex)) < 0)
              std::swap(t[1], t[2]);
            if (orient3d(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3])) <=
                0) {
              valid = false;
              break;
            }
            mn = std::min(mn, tet_objective(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]),
                                            mesh.point(t[3])));
            tets.push_back(t);
          }
          if (!valid || mn <= std::max(best_min, old_min + o.min_gain)) {
            valid = false;
            break;
          }
        }
        if (valid && mn > best_min) {
          best_min = mn;
          best_tets = tets;
        }
      }
      if (best_min <= old_min + o.min_gain) continue;
      // The fold check first: a few normals, against the Hausdorff check's distance queries.
      if (flip_folds_surface(mesh, fans, p.f1, p.f2, a, b, c, d, cos_flat)) continue;
      if (!surface_flip_within(mesh, model, fans, p.f1, p.f2, a, b, c, d, o.hausdorff)) continue;
      // Volume change: new minus old.
      double dv = 0;
      for (const auto& t : best_tets)
        dv += tet_volume(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3]));
      for (int t : p.ring) {
        const int* w = &mesh.tets[4 * static_cast<std::size_t>(t)];
        dv -= tet_volume(mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]), mesh.point(w[3]));
      }
      if (o.volume_budget) {
        VolumeBudget& vb = *o.volume_budget;
        p.delta.assign(vb.region.size(), 0);
        bool fits = true;
        for (std::size_t i = 0; i < vb.region.size(); ++i)
          if (vb.region[i] == p.region) {
            p.delta[i] = dv;
            fits = std::fabs(vb.change[i] + dv) <= vb.tolerance * std::fabs(vb.volume[i]);
          }
        if (!fits) continue;
        vb.commit(p.delta);
      }
      // Apply: kill the ring, append the new tets, retarget the two triangles. Every vertex of
      // the ring has a stale star now: none is touched again in this pass.
      for (int t : p.ring)
        for (int j = 0; j < 4; ++j) dirty[mesh.tets[4 * static_cast<std::size_t>(t) + j]] = 1;
      apply_boundary_retriangulation(mesh, p.ring, best_tets, p.region);
      retarget_flipped_triangles(mesh, p.f1, p.f2, a, b, c, d);
      ++flipped;
      ++stats.nb_flipped;
    }
    if (flipped) {
      // The dead slots must not be read by the next pass's stars: compact now.
      compact_tets(mesh);
      changed_any = true;
    }
    if (flipped == 0) break;
  }
  if (changed_any && mesh.adj.size() != mesh.tets.size()) build_adjacency(mesh);
  return stats;
}

}  // namespace cvtmesh
