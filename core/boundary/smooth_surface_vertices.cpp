#include "core/boundary/smooth_surface_vertices.h"

#include <algorithm>
#include <cmath>

#include "core/boundary/boundary_move.h"
#include "core/geometry/predicates.h"
#include "core/geometry/tet_geometry.h"
#include "core/geometry/vec3.h"
#include "core/mesh/vertex_tets.h"
#include "core/quality/quality.h"

namespace cvtmesh {
namespace {

const double* corner(const TetMesh& m, int w, int v, const double* position) {
  return w == v ? position : m.point(w);
}

// v's fan triangle f as (v, b, c) in f's turning order.
void fan_triangle(const TetMesh& m, int f, int v, int& b, int& c) {
  const int* t = &m.tris[3 * static_cast<std::size_t>(f)];
  for (int k = 0; k < 3; ++k)
    if (t[k] == v) {
      b = t[(k + 1) % 3];
      c = t[(k + 2) % 3];
      return;
    }
  b = c = -1;
}

// The part of triangle (p, q, r) nearer to p than to q and r: the triangle clipped by the two
// bisector planes; its area and centroid.
void voronoi_part(const Vec3& p, const Vec3& q, const Vec3& r, double& area, Vec3& centroid) {
  std::vector<Vec3> poly = {p, q, r};
  for (const Vec3& o : {q, r}) {
    const Vec3 mid = 0.5 * (p + o), dir = o - p;
    std::vector<Vec3> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec3& s = poly[i];
      const Vec3& e = poly[(i + 1) % poly.size()];
      const double ds = dot(s - mid, dir), de = dot(e - mid, dir);
      if (ds <= 0) out.push_back(s);
      if ((ds < 0 && de > 0) || (ds > 0 && de < 0)) out.push_back(s + (ds / (ds - de)) * (e - s));
    }
    poly.swap(out);
    if (poly.size() < 3) break;
  }
  area = 0;
  centroid = {0, 0, 0};
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const double a = 0.5 * norm(cross(poly[i] - poly[0], poly[i + 1] - poly[0]));
    area += a;
    centroid = centroid + (a / 3) * (poly[0] + poly[i] + poly[i + 1]);
  }
  if (area > 0) centroid = (1 / area) * centroid;
}

// Whether every fan triangle keeps its turning sense with v at `position`: exact orient3d of the
// triangle against a point on its old normal, before and after.
bool fan_keeps_orientation(const TetMesh& m, const BoundaryFans& fans, int v,
                           const double* position) {
  for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f) {
    const int* t = &m.tris[3 * static_cast<std::size_t>(*f)];
    const double *a = m.point(t[0]), *b = m.point(t[1]), *c = m.point(t[2]);
    const Vec3 n = cross(sub(b, a), sub(c, a));
    const double l = norm(n);
    if (!(l > 0)) continue;  // a flat triangle: any position is no worse
    const double len = std::sqrt(std::max({dist2(a, b), dist2(b, c), dist2(c, a)}));
    double eye[3];
    for (int k = 0; k < 3; ++k) eye[k] = (a[k] + b[k] + c[k]) / 3 + len * n[k] / l;
    const double before = orient3d(a, b, c, eye);
    const double after = orient3d(corner(m, t[0], v, position), corner(m, t[1], v, position),
                                  corner(m, t[2], v, position), eye);
    if (after == 0 || (before > 0) != (after > 0)) return false;
  }
  return true;
}

}  // namespace

FanQuality fan_quality(const TetMesh& m, const BoundaryFans& fans, int v, const double* position) {
  FanQuality q;
  for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f) {
    const int* t = &m.tris[3 * static_cast<std::size_t>(*f)];
    const double *a = corner(m, t[0], v, position), *b = corner(m, t[1], v, position),
                 *c = corner(m, t[2], v, position);
    q.min_angle = std::min(q.min_angle, tri_quality(a, b, c, 3, Measure::kMinAngle));
    q.q_min = std::min(q.q_min, tri_quality(a, b, c, 3, Measure::kQ));
    q.max_angle = std::max(q.max_angle, tri_quality(a, b, c, 3, Measure::kMaxAngle));
  }
  return q;
}

SurfaceMoveStats smooth_surface_vertices(TetMesh& m, const BoundaryModel& model,
                                         const BoundaryFans& fans, const std::vector<int>& vertices,
                                         const SurfaceMoveOptions& o) {
  SurfaceMoveStats st;
  const VertexTets no_tets{std::vector<int>(static_cast<std::size_t>(m.nb_vertices()) + 1, 0), {}};
  for (int v : vertices) {
    if (!model.movable(v) || fans.begin_of(v) == fans.end_of(v)) continue;
    const Vec3 p = vec3(m.point(v));
    const FanQuality old_q = fan_quality(m, fans, v, m.point(v));
    // Accepts `wanted` (projected and checked) if it keeps the fan within its floors; `gain`:
    // the fan's minimum angle must rise.
    auto try_move = [&](const Vec3& wanted, bool gain, FanQuality& got, double* at) {
      ++st.nb_tried;
      const PlannedBoundaryMove plan =
          plan_boundary_move(m, model, no_tets, fans, v, wanted.data(), o.hausdorff);
      if (plan.status != BoundaryMoveStatus::kOk) return false;
      if (!fan_keeps_orientation(m, fans, v, plan.position)) return false;
      got = fan_quality(m, fans, v, plan.position);
      if (got.q_min < std::min(old_q.q_min, o.q_floor) ||
          got.min_angle < std::min(old_q.min_angle, o.angle_floor) ||
          got.max_angle > std::max(old_q.max_angle, o.angle_ceiling))
        return false;
      if (gain && !(got.min_angle > old_q.min_angle)) return false;
      std::copy(plan.position, plan.position + 3, at);
      return true;
    };
    double best[3];
    bool found = false;
    if (o.kind == SurfaceMoveKind::kCentroid) {
      double area = 0;
      Vec3 c = {0, 0, 0};
      for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f) {
        int b, cc;
        fan_triangle(m, *f, v, b, cc);
        if (b < 0) continue;
        double a;
        Vec3 g;
        voronoi_part(p, vec3(m.point(b)), vec3(m.point(cc)), a, g);
        if (o.sizes) {
          const double h = ((*o.sizes)[v] + (*o.sizes)[b] + (*o.sizes)[cc]) / 3;
          if (h > 0) a /= h * h * h * h;
        }
        area += a;
        c = c + a * g;
      }
      if (!(area > 0)) continue;
      c = (1 / area) * c;
      FanQuality got;
      for (double w : {o.relaxation, 0.5 * o.relaxation}) {
        if (try_move(p + w * (c - p), false, got, best)) {
          found = true;
          break;
        }
      }
    } else {
      // Angle-based target: for each fan triangle (v, b, c), the apex over (b, c) of the
      // equilateral triangle on v's side, in the triangle's plane; and the neighbours' average.
      Vec3 angle_target = {0, 0, 0}, lap = {0, 0, 0};
      int n = 0;
      for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f) {
        int b, cc;
        fan_triangle(m, *f, v, b, cc);
        if (b < 0) continue;
        const Vec3 pb = vec3(m.point(b)), pc = vec3(m.point(cc));
        const Vec3 mid = 0.5 * (pb + pc), e = pc - pb;
        const Vec3 nrm = cross(pb - p, pc - p);
        Vec3 up = cross(nrm, e);  // in the plane, perpendicular to (b, c)
        const double lu = norm(up);
        if (!(lu > 0)) continue;
        up = (1 / lu) * up;
        if (dot(up, p - mid) < 0) up = -1.0 * up;
        angle_target = angle_target + (mid + (std::sqrt(3.0) / 2 * norm(e)) * up);
        lap = lap + 0.5 * (pb + pc);
        ++n;
      }
      if (!n) continue;
      angle_target = (1.0 / n) * angle_target;
      lap = (1.0 / n) * lap;
      FanQuality best_q = old_q;
      for (const Vec3& target : {angle_target, lap})
        for (double w : {1.0, 0.5, 0.25}) {
          FanQuality got;
          double at[3];
          if (try_move(p + w * (target - p), true, got, at) && got.min_angle > best_q.min_angle) {
            best_q = got;
            std::copy(at, at + 3, best);
            found = true;
          }
        }
    }
    if (!found) continue;
    st.max_step = std::max(st.max_step, std::sqrt(dist2(best, p.data())));
    double* q = m.point(v);
    std::copy(best, best + 3, q);
    ++st.nb_moved;
  }
  return st;
}

}  // namespace cvtmesh
