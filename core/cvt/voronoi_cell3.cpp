#include "core/cvt/voronoi_cell3.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <unordered_set>

#include "core/geometry/predicates.h"
#include "core/geometry/tet_geometry.h"
#include "core/mesh/face_key.h"

namespace cvtmesh {

void constrained_face_flags(const TetMesh& m, std::vector<char>& flags) {
  // Only a face whose three vertices are on constrained triangles can be one: hash those only.
  std::unordered_set<FaceKey, FaceKeyHash> cf;
  cf.reserve(2 * m.tris.size() / 3 + 1);
  std::vector<char> on(m.nb_vertices(), 0);
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* v = &m.tris[3 * f];
    cf.insert(face_key(v[0], v[1], v[2]));
    on[v[0]] = on[v[1]] = on[v[2]] = 1;
  }
  flags.assign(m.tets.size(), 0);
  const int nt = m.nb_tets();
  // In parallel: the set is only read (once per Lloyd iteration, ~0.2 s of one thread at 10M tets).
#pragma omp parallel for schedule(static, 4096)
  for (int t = 0; t < nt; ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] < 0) continue;
    for (int f = 0; f < 4; ++f) {
      const int a = v[kTetFace[f][0]], b = v[kTetFace[f][1]], c = v[kTetFace[f][2]];
      flags[4 * t + f] =
          m.adj[4 * t + f] < 0 || (on[a] && on[b] && on[c] && cf.count(face_key(a, b, c)) > 0);
    }
  }
}

Vec3 CellIntegrals::centroid(const double* z) const {
  if (!(mass > 0)) return vec3(z);
  return {z[0] + moment[0] / mass, z[1] + moment[1] / mass, z[2] + moment[2] / mass};
}

namespace {

// The P1 density of tet t written around z: rho(x) = r0 + g.(x - z).
void linear_density(const TetMesh& m, int t, const std::vector<double>& rho, const Vec3& z,
                    double& r0, Vec3& g) {
  density_gradient(m, t, rho, g.data());
  const int* v = &m.tets[4 * t];
  const double* p0 = m.point(v[0]);
  r0 = rho[v[0]] + g[0] * (z[0] - p0[0]) + g[1] * (z[1] - p0[1]) + g[2] * (z[2] - p0[2]);
}

}  // namespace

namespace {

// The cell of v clipped by the bisectors of `generators`; `hit` receives the tets where the cell
// has a piece of positive volume.
CellIntegrals integrate_cell(const TetMesh& m, const CellMesh& cm, int v, CellWorkspace& ws,
                             const std::vector<double>* rho, const std::vector<int>& generators,
                             std::vector<int>& hit) {
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
  // Bisector half-spaces n.(x - z) <= h with unit n = (w - z)/|w - z| and h = |w - z|/2, sorted
  // by h: a piece whose points are all within h of z cannot be cut by this plane or any later one.
  std::vector<PlaneRef>& planes = ws.planes;
  planes.clear();
  for (int w : generators) {
    const Vec3 n = vec3(m.point(w)) - z;
    const double len = norm(n);
    if (!(len > 0)) continue;
    const Vec3 u = (1.0 / len) * n;
    planes.push_back({u, 0.5 * len, cm.eps * norm(u)});
  }
  std::sort(planes.begin(), planes.end(),
            [](const PlaneRef& a, const PlaneRef& b) { return a.h < b.h; });
  ws.queue.clear();
  for (const int* it = cm.star.begin_of(v); it != cm.star.end_of(v); ++it) {
    ws.mark[*it] = ws.stamp;
    ws.queue.push_back(*it);
  }
  for (std::size_t qi = 0; qi < ws.queue.size(); ++qi) {
    const int t = ws.queue[qi];
    const int* tv = &m.tets[4 * t];
    // Work relative to z (the planes pass at distance h from the origin).
    Vec3 q[4];
    double reach2 = 0;  // max |x - z|^2 over the current piece
    for (int k = 0; k < 4; ++k) {
      q[k] = vec3(m.point(tv[k])) - z;
      reach2 = std::max(reach2, norm2(q[k]));
    }
    Polytope& p = ws.poly;
    bool started = false, alive = true;
    for (std::size_t k = 0; k < planes.size() && alive; ++k) {
      const PlaneRef& pl = planes[k];
      if (pl.h * pl.h >= reach2) break;
      if (!started) {
        int in = 0, out = 0;
        for (const Vec3& x : q) {
          const double sd = dot(pl.n, x) - pl.h;
          in += sd <= 0;
          out += sd > 0;
        }
        if (out == 0) continue;
        if (in == 0) {
          alive = false;
          break;
        }
        tet_polytope(q[0].data(), q[1].data(), q[2].data(), q[3].data(), p);
        started = true;
      }
      // (clip_polytope's tolerance, eps |n|, taken once per plane; a plane that cuts nothing
      // leaves the piece and its reach as they were.)
      if (!(pl.tol > 0)) continue;
      bool changed = false;
      alive = clip_polytope_tol(p, pl.n, pl.h, 4, pl.tol, ws.scratch, changed);
      if (alive && changed) {
        reach2 = 0;
        for (const Vec3& x : p.vtx) reach2 = std::max(reach2, norm2(x));
      }
    }
    if (!alive) continue;
    if (!started) tet_polytope(q[0].data(), q[1].data(), q[2].data(), q[3].data(), p);
    const Moments mt = polytope_moments(p, Vec3{0, 0, 0});
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
      if (cm.constrained[4 * t + f]) continue;
      const int o = m.adj[4 * t + f];
      if (o < 0) continue;
      const int t2 = o / 4;
      if (ws.mark[t2] == ws.stamp) continue;
      if (face_area(p, f) <= cm.eps * cm.eps) continue;
      ws.mark[t2] = ws.stamp;
      ws.queue.push_back(t2);
    }
  }
  return total;
}

// Adds the vertices of tet t other than v to `out`, each once per list: a vertex whose mark is
// the list's stamp is in it already. (The lists were sorted with their repeats, ~20 per vertex,
// then made unique: 4 % of the first Lloyd of igl_bunny, whose boundary cells are clipped.)
inline void add_tet_vertices(const TetMesh& m, int t, int v, std::vector<int>& out,
                             std::vector<int>& mark, int stamp) {
  for (int k = 0; k < 4; ++k) {
    const int w = m.tets[4 * t + k];
    if (w != v && mark[w] != stamp) {
      mark[w] = stamp;
      out.push_back(w);
    }
  }
}

// A new stamp for a list of add_tet_vertices.
inline int next_vertex_stamp(const TetMesh& m, CellWorkspace& ws) {
  if (static_cast<int>(ws.vmark.size()) != m.nb_vertices()) ws.vmark.assign(m.nb_vertices(), -1);
  if (++ws.vstamp == 0x7fffffff) {
    std::fill(ws.vmark.begin(), ws.vmark.end(), -1);
    ws.vstamp = 1;
  }
  return ws.vstamp;
}

}  // namespace

CellIntegrals restricted_voronoi_cell(const TetMesh& m, const CellMesh& cm, int v,
                                      CellWorkspace& ws, const std::vector<double>* rho) {
  // Generators: the vertices of the star and of the tets across its unconstrained faces (the
  // cell of a boundary vertex of a constrained mesh often reaches one tet beyond its star).
  std::vector<int>& gens = ws.generators;
  gens.clear();
  const int gen_stamp = next_vertex_stamp(m, ws);
  for (const int* it = cm.star.begin_of(v); it != cm.star.end_of(v); ++it) {
    const int t = *it;
    add_tet_vertices(m, t, v, gens, ws.vmark, gen_stamp);
    for (int f = 0; f < 4; ++f) {
      const int o = m.adj[4 * t + f];
      if (o >= 0 && !cm.constrained[4 * t + f])
        add_tet_vertices(m, o / 4, v, gens, ws.vmark, gen_stamp);
    }
  }
  std::sort(gens.begin(), gens.end());
  CellIntegrals c;
  // Until the cell reaches no tet with a vertex that is not a generator (bounded: the set grows).
  for (int pass = 0; pass < 8; ++pass) {
    c = integrate_cell(m, cm, v, ws, rho, gens, ws.hit);
    ws.reached.clear();
    const int reached_stamp = next_vertex_stamp(m, ws);
    for (int t : ws.hit) add_tet_vertices(m, t, v, ws.reached, ws.vmark, reached_stamp);
    std::sort(ws.reached.begin(), ws.reached.end());
    if (std::includes(gens.begin(), gens.end(), ws.reached.begin(), ws.reached.end())) break;
    std::vector<int> merged;
    merged.reserve(gens.size() + ws.reached.size());
    std::set_union(gens.begin(), gens.end(), ws.reached.begin(), ws.reached.end(),
                   std::back_inserter(merged));
    gens.swap(merged);
  }
  return c;
}

namespace {

// The six signed tets (z, a_e, f_j, c) of local vertex k (coordinates relative to z = p_k: a_e
// the half edges to the other vertices, f_j the circumcentres of the faces through z, c the tet's)
// summed with the terms every piece shares taken once: the dot products
// with g and the squared norms of the seven points, the cross products f_j x c, and the moment
// as one weighted sum of the seven points (each piece's moment, 0.25 vol r0 s + vol/20 (s.g s
// + sum p.g p) with s = a + f + c, is a combination of its own three points). The same integrals
// to rounding. dual_tet_pieces was 20 % of the samples of `perf record cvtmesh optimize c1m.msh`
// with six separate signed tets per vertex; the Lloyd iterations' cell time of that run fell
// 11.1 -> 7.8 s (docs/benchmarks.md, stop 30).
void vertex_dual_piece(const Vec3 a[3], const Vec3 f[3], const Vec3& c, double r0, const Vec3& g,
                       double* out) {
  double ag[3], aa[3], fg[3], ff[3];
  Vec3 x[3];
  for (int i = 0; i < 3; ++i) {
    ag[i] = dot(a[i], g);
    aa[i] = norm2(a[i]);
    fg[i] = dot(f[i], g);
    ff[i] = norm2(f[i]);
    x[i] = cross(f[i], c);
  }
  const double cg = dot(c, g), cc = norm2(c);
  // In units of six times the pieces' volumes d (one scaling at the end, no division per piece):
  // vol = d / 6, vol / 20 = d / 120, and a piece's moment coefficient of each of its points,
  // 0.25 vol r0 + vol / 20 (s.g + p.g), is d / 120 (5 r0 + s.g + p.g).
  double A[3] = {0, 0, 0}, F[3] = {0, 0, 0}, C = 0;
  double volume = 0, mass = 0, energy = 0;
  const double r5 = 5.0 * r0;
  for (int e = 0; e < 3; ++e)
    for (int side = 0; side < 2; ++side) {
      // Edge e's piece on the face opposite ring[e + 2] is positive, on the one opposite
      // ring[e + 1] negative (vertex_dual_piece's caller orders the faces by ring).
      const int j = side == 0 ? (e + 2) % 3 : (e + 1) % 3;
      const double d = side == 0 ? dot(a[e], x[j]) : -dot(a[e], x[j]);
      const Vec3 s = (a[e] + f[j]) + c;
      const double sg = (ag[e] + fg[j]) + cg;
      const double base = r5 + sg;
      A[e] += d * (base + ag[e]);
      F[j] += d * (base + fg[j]);
      C += d * (base + cg);
      const double rho_mean = r0 + 0.25 * sg;
      volume += d;
      mass += d * rho_mean;
      energy += d * rho_mean * (((norm2(s) + aa[e]) + ff[j]) + cc);
    }
  constexpr double kSixth = 1.0 / 6.0, kOver120 = 1.0 / 120.0;
  Vec3 moment = C * c;
  for (int i = 0; i < 3; ++i) moment = moment + (A[i] * a[i] + F[i] * f[i]);
  moment = kOver120 * moment;
  volume *= kSixth;
  mass *= kSixth;
  energy *= kOver120;
  out[0] = volume;
  out[1] = mass;
  out[2] = moment[0];
  out[3] = moment[1];
  out[4] = moment[2];
  out[5] = energy;
}

}  // namespace

void dual_tet_pieces(const TetMesh& m, int t, const Vec3& cc, const std::vector<double>* rho,
                     const double* grad, double* out) {
  const int* tv = &m.tets[4 * t];
  const double* p[4] = {m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])};
  Vec3 fcc[4];
  for (int f = 0; f < 4; ++f)
    fcc[f] = tri_circumcenter3d(p[kTetFace[f][0]], p[kTetFace[f][1]], p[kTetFace[f][2]]);
  const Vec3 g = grad ? Vec3{grad[0], grad[1], grad[2]} : Vec3{0, 0, 0};
  // For local vertex k, (k, a, b, c) with the same orientation as the tet (an even permutation
  // moving k first).
  static const int kRest[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (int k = 0; k < 4; ++k) {
    const Vec3 z = vec3(p[k]);
    const double r0 = rho ? (*rho)[tv[k]] : 1.0;
    const int* ring = kRest[k];
    Vec3 a[3], f[3];
    for (int i = 0; i < 3; ++i) {
      a[i] = 0.5 * (vec3(p[ring[i]]) - z);
      f[i] = fcc[ring[i]] - z;
    }
    vertex_dual_piece(a, f, cc - z, r0, g, out + 6 * k);
  }
}

bool dual_voronoi_cell(const TetMesh& m, const CellMesh& cm, int v, CellIntegrals& out) {
  // One pass over the star: the sums in star order, abandoned at the first tet without its dual
  // pieces (the caller then clips the cell and discards `out`).
  out = CellIntegrals{};
  for (const int* it = cm.star.begin_of(v); it != cm.star.end_of(v); ++it) {
    const int t = *it;
    if (!cm.dual_ok[t]) return false;
    const int* tv = &m.tets[4 * t];
    int k = 0;
    while (tv[k] != v) ++k;
    const double* o = &cm.dual_piece[24 * t + 6 * k];
    out.volume += o[0];
    out.mass += o[1];
    out.moment = out.moment + Vec3{o[2], o[3], o[4]};
    out.energy += o[5];
  }
  return out.volume > 0;
}

}  // namespace cvtmesh
