#include "core/cvt/voronoi_cell3.h"

#include <algorithm>
#include <unordered_set>

#include "core/geometry/predicates.h"
#include "core/geometry/tet_geometry.h"
#include "core/mesh/face_key.h"
#include "core/mesh/locate_point.h"

namespace cvtmesh {

std::vector<char> constrained_face_flags(const TetMesh& m) {
  std::unordered_set<FaceKey, FaceKeyHash> cf;
  cf.reserve(2 * m.tris.size() / 3 + 1);
  for (int f = 0; f < m.nb_tris(); ++f)
    cf.insert(face_key(m.tris[3 * f], m.tris[3 * f + 1], m.tris[3 * f + 2]));
  std::vector<char> flags(m.tets.size(), 0);
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] < 0) continue;
    for (int f = 0; f < 4; ++f)
      flags[4 * t + f] =
          m.adj[4 * t + f] < 0 ||
          cf.count(face_key(v[kTetFace[f][0]], v[kTetFace[f][1]], v[kTetFace[f][2]])) > 0;
  }
  return flags;
}

Vec3 CellIntegrals::centroid(const double* z) const {
  if (!(mass > 0)) return vec3(z);
  return {z[0] + moment[0] / mass, z[1] + moment[1] / mass, z[2] + moment[2] / mass};
}

namespace {

// The P1 density of tet t written around z: rho(x) = r0 + g.(x - z).
void linear_density(const TetMesh& m, int t, const std::vector<double>& rho, const Vec3& z,
                    double& r0, Vec3& g) {
  const int* v = &m.tets[4 * t];
  const double* p0 = m.point(v[0]);
  double E[3][3], rhs[3];
  for (int k = 0; k < 3; ++k) {
    const double* pk = m.point(v[k + 1]);
    for (int d = 0; d < 3; ++d) E[k][d] = pk[d] - p0[d];
    rhs[k] = rho[v[k + 1]] - rho[v[0]];
  }
  const double det = E[0][0] * (E[1][1] * E[2][2] - E[1][2] * E[2][1]) -
                     E[0][1] * (E[1][0] * E[2][2] - E[1][2] * E[2][0]) +
                     E[0][2] * (E[1][0] * E[2][1] - E[1][1] * E[2][0]);
  if (det == 0) {
    g = {0, 0, 0};
  } else {
    // g = E^-1 rhs via the adjugate.
    const double inv[3][3] = {{(E[1][1] * E[2][2] - E[1][2] * E[2][1]) / det,
                               (E[0][2] * E[2][1] - E[0][1] * E[2][2]) / det,
                               (E[0][1] * E[1][2] - E[0][2] * E[1][1]) / det},
                              {(E[1][2] * E[2][0] - E[1][0] * E[2][2]) / det,
                               (E[0][0] * E[2][2] - E[0][2] * E[2][0]) / det,
                               (E[0][2] * E[1][0] - E[0][0] * E[1][2]) / det},
                              {(E[1][0] * E[2][1] - E[1][1] * E[2][0]) / det,
                               (E[0][1] * E[2][0] - E[0][0] * E[2][1]) / det,
                               (E[0][0] * E[1][1] - E[0][1] * E[1][0]) / det}};
    for (int r = 0; r < 3; ++r) g[r] = inv[r][0] * rhs[0] + inv[r][1] * rhs[1] + inv[r][2] * rhs[2];
  }
  r0 = rho[v[0]] + g[0] * (z[0] - p0[0]) + g[1] * (z[1] - p0[1]) + g[2] * (z[2] - p0[2]);
}

}  // namespace

namespace {

// The cell of v clipped by the bisectors of the generators `nbrs`; `hit` receives the tets where
// the cell has a piece of positive volume.
CellIntegrals integrate_cell(const TetMesh& m, const VertexStar& star,
                             const std::vector<char>& constrained, int v, double eps,
                             CellWorkspace& ws, const std::vector<double>* rho,
                             const std::vector<int>& nbrs, std::vector<int>& hit) {
  CellIntegrals total;
  hit.clear();
  const int nt = m.nb_tets();
  if (static_cast<int>(ws.mark.size()) != nt) ws.mark.assign(nt, -1);
  ++ws.stamp;
  if (ws.stamp == 0x7fffffff) {
    std::fill(ws.mark.begin(), ws.mark.end(), -1);
    ws.stamp = 1;
  }
  const Vec3 z = vec3(m.point(v));
  // Bisector half-spaces (x - mid).(w - z) <= 0.
  std::vector<Vec3>& normals = ws.normals;
  std::vector<double>& offsets = ws.offsets;
  normals.clear();
  offsets.clear();
  for (int w : nbrs) {
    const Vec3 pw = vec3(m.point(w));
    const Vec3 n = pw - z;
    normals.push_back(n);
    offsets.push_back(0.5 * (dot(n, pw) + dot(n, z)));
  }
  ws.queue.clear();
  for (int i = star.offset[v]; i < star.offset[v + 1]; ++i) {
    const int t = star.tets[i];
    ws.mark[t] = ws.stamp;
    ws.queue.push_back(t);
  }
  for (std::size_t qi = 0; qi < ws.queue.size(); ++qi) {
    const int t = ws.queue[qi];
    const int* tv = &m.tets[4 * t];
    Polytope& p = ws.poly;
    tet_polytope(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3]), p);
    bool alive = true;
    const Vec3 q[4] = {vec3(m.point(tv[0])), vec3(m.point(tv[1])), vec3(m.point(tv[2])),
                       vec3(m.point(tv[3]))};
    for (std::size_t k = 0; k < normals.size() && alive; ++k) {
      // A plane that keeps the whole tet cannot cut the piece: skip it; one that keeps none of
      // it empties the piece.
      int in = 0, out = 0;
      for (const Vec3& x : q) {
        const double sd = dot(normals[k], x) - offsets[k];
        in += sd <= 0;
        out += sd > 0;
      }
      if (out == 0) continue;
      if (in == 0) {
        alive = false;
        break;
      }
      alive = clip_polytope(p, normals[k], offsets[k], 4, eps, ws.scratch);
    }
    if (!alive) continue;
    const Moments mt = polytope_moments(p, z);
    if (mt.m0 <= 0) continue;
    hit.push_back(t);
    total.volume += mt.m0;
    const double tr = mt.m2[0] + mt.m2[4] + mt.m2[8];
    if (!rho) {
      total.mass += mt.m0;
      total.moment = total.moment + mt.m1;
      total.energy += tr;
    } else {
      double r0;
      Vec3 g;
      linear_density(m, t, *rho, z, r0, g);
      total.mass += r0 * mt.m0 + dot(g, mt.m1);
      Vec3 mom = r0 * mt.m1;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) mom[r] += mt.m2[3 * r + c] * g[c];
      total.moment = total.moment + mom;
      total.energy += (r0 + dot(g, (1.0 / mt.m0) * mt.m1)) * tr;
    }
    // Continue through the faces of t that the clipped cell still touches.
    for (int f = 0; f < 4; ++f) {
      if (constrained[4 * t + f]) continue;
      const int o = m.adj[4 * t + f];
      if (o < 0) continue;
      const int t2 = o / 4;
      if (ws.mark[t2] == ws.stamp) continue;
      if (face_area(p, f) <= eps * eps) continue;
      ws.mark[t2] = ws.stamp;
      ws.queue.push_back(t2);
    }
  }
  return total;
}

}  // namespace

CellIntegrals restricted_voronoi_cell(const TetMesh& m, const VertexStar& star,
                                      const std::vector<char>& constrained, int v, double eps,
                                      CellWorkspace& ws, const std::vector<double>* rho) {
  // First with the Delaunay neighbours; where the mesh is not Delaunay (a constrained mesh near
  // its boundary) other generators can be nearer: redo the cell with every vertex of the tets it
  // reached, so that the cells do not overlap.
  std::vector<int> nbrs = vertex_neighbors(m, star, v);
  std::vector<int> hit;
  CellIntegrals c = integrate_cell(m, star, constrained, v, eps, ws, rho, nbrs, hit);
  std::vector<int> more = nbrs;
  for (int t : hit)
    for (int k = 0; k < 4; ++k) {
      const int w = m.tets[4 * t + k];
      if (w != v) more.push_back(w);
    }
  std::sort(more.begin(), more.end());
  more.erase(std::unique(more.begin(), more.end()), more.end());
  if (more.size() == nbrs.size()) return c;
  return integrate_cell(m, star, constrained, v, eps, ws, rho, more, hit);
}

std::vector<double> tet_circumcenters(const TetMesh& m) {
  std::vector<double> cc(3 * static_cast<std::size_t>(m.nb_tets()), 0.0);
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] < 0) continue;
    const Vec3 c = tet_circumcenter(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
    for (int d = 0; d < 3; ++d) cc[3 * t + d] = c[d];
  }
  return cc;
}

namespace {

// Adds the integrals of the signed tet (z, a, b, c) (coordinates relative to z), times sign.
void add_signed_tet(const Vec3& a, const Vec3& b, const Vec3& c, double sign, double r0,
                    const Vec3& g, CellIntegrals& out) {
  const double vol = sign * dot(a, cross(b, c)) / 6.0;
  if (vol == 0) return;
  const Vec3 s = (a + b) + c;  // + z = 0
  const Vec3 m1 = (vol / 4.0) * s;
  double m2[9];
  const Vec3* pts[3] = {&a, &b, &c};
  for (int r = 0; r < 3; ++r)
    for (int q = 0; q < 3; ++q) {
      double acc = s[r] * s[q];
      for (const Vec3* p : pts) acc += (*p)[r] * (*p)[q];
      m2[3 * r + q] = vol / 20.0 * acc;
    }
  const double tr = m2[0] + m2[4] + m2[8];
  out.volume += vol;
  out.mass += r0 * vol + dot(g, m1);
  Vec3 mom = r0 * m1;
  for (int r = 0; r < 3; ++r)
    for (int q = 0; q < 3; ++q) mom[r] += m2[3 * r + q] * g[q];
  out.moment = out.moment + mom;
  out.energy += (r0 + dot(g, (1.0 / vol) * m1)) * tr;
}

}  // namespace

bool dual_voronoi_cell(const TetMesh& m, const VertexStar& star,
                       const std::vector<char>& constrained, const std::vector<double>& cc, int v,
                       const std::vector<double>* rho, CellIntegrals& out) {
  out = CellIntegrals{};
  if (m.vclass[v].dim != 3) return false;
  for (int i = star.offset[v]; i < star.offset[v + 1]; ++i) {
    const int t = star.tets[i];
    for (int f = 0; f < 4; ++f)
      if (constrained[4 * t + f]) return false;
    const LocateResult r = locate_point(m, &cc[3 * t], t, &constrained, 16);
    if (r.status != LocateStatus::kInside) return false;
    // The dual decomposition is exact only where the mesh is Delaunay: every neighbour's opposite
    // vertex must be outside the circumsphere (a constrained mesh can break this near the
    // boundary).
    const int* tv = &m.tets[4 * t];
    for (int f = 0; f < 4; ++f) {
      const int o = m.adj[4 * t + f];
      if (o < 0) continue;
      const int opp = m.tets[4 * (o / 4) + o % 4];
      if (insphere(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3]), m.point(opp)) >
          0)
        return false;
    }
  }
  const Vec3 z = vec3(m.point(v));
  for (int i = star.offset[v]; i < star.offset[v + 1]; ++i) {
    const int t = star.tets[i];
    const int* tv = &m.tets[4 * t];
    int k = 0;
    while (tv[k] != v) ++k;
    // (v, a, b, c) with the same orientation as the tet (an even permutation moving v first).
    static const int kRest[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    const int a = tv[kRest[k][0]], b = tv[kRest[k][1]], c = tv[kRest[k][2]];
    double r0 = 1;
    Vec3 g{0, 0, 0};
    if (rho) linear_density(m, t, *rho, z, r0, g);
    const Vec3 ct = Vec3{cc[3 * t], cc[3 * t + 1], cc[3 * t + 2]} - z;
    const int ring[3] = {a, b, c};
    for (int e = 0; e < 3; ++e) {
      const int w = ring[e], u1 = ring[(e + 1) % 3], u2 = ring[(e + 2) % 3];
      const Vec3 me = 0.5 * (vec3(m.point(w)) - z);
      // Face (v, w, u1) with fourth vertex u2: orientation of (v, w, u1, u2) is that of the tet
      // for (a,b,c) cyclic; face (v, w, u2) with fourth u1 has the opposite orientation.
      const Vec3 c1 = tri_circumcenter3d(m.point(v), m.point(w), m.point(u1)) - z;
      const Vec3 c2 = tri_circumcenter3d(m.point(v), m.point(w), m.point(u2)) - z;
      add_signed_tet(me, c1, ct, +1.0, r0, g, out);
      add_signed_tet(me, c2, ct, -1.0, r0, g, out);
    }
  }
  return out.volume > 0;
}

}  // namespace cvtmesh
