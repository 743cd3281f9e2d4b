#include "core/boundary/raise_nodal_steps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/pattern_move.h"
#include "core/geometry/predicates.h"
#include "core/geometry/vec3.h"
#include "core/mesh/vertex_tets.h"
#include "core/quality/element_time_step.h"
#include "core/quality/quality.h"
#include "core/quality/vertex_time_step.h"

namespace cvtmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

const int* tet_of(const TetMesh& m, int t) {
  return &m.tets[4 * static_cast<std::size_t>(t)];
}

// The mover w's star: its tets, their vertices and, per vertex, its nodal sums over its tets
// outside the star (what a move of w does not change).
struct Star {
  std::vector<int> tets;
  std::vector<double> ceiling;  // per tet: its maximum dihedral angle's bound (degrees)
  std::vector<int> verts;
  std::vector<double> k_rest, m_rest;
};

Star star_of(const TetMesh& mesh, const VertexTets& vt, const VertexTimeSteps& steps, int w,
             const NodalRaiseOptions& o) {
  Star s;
  s.tets.assign(vt.begin_of(w), vt.end_of(w));
  for (int t : s.tets)
    for (int k = 0; k < 4; ++k)
      if (std::find(s.verts.begin(), s.verts.end(), tet_of(mesh, t)[k]) == s.verts.end())
        s.verts.push_back(tet_of(mesh, t)[k]);
  for (int t : s.tets) {
    const int* v = tet_of(mesh, t);
    s.ceiling.push_back(
        std::max(o.angle_ceiling, tet_table_qualities(mesh.point(v[0]), mesh.point(v[1]),
                                                      mesh.point(v[2]), mesh.point(v[3]))[3]));
  }
  s.k_rest.resize(s.verts.size());
  s.m_rest.resize(s.verts.size());
  for (std::size_t i = 0; i < s.verts.size(); ++i) {
    s.k_rest[i] = steps.kdiag[s.verts[i]];
    s.m_rest[i] = steps.mass[s.verts[i]];
  }
  for (int t : s.tets) {
    const int* v = tet_of(mesh, t);
    double k[4], m;
    tet_vertex_terms(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]), k, &m);
    for (int j = 0; j < 4; ++j) {
      const std::size_t i = std::find(s.verts.begin(), s.verts.end(), v[j]) - s.verts.begin();
      s.k_rest[i] -= k[j];
      s.m_rest[i] -= m;
    }
  }
  return s;
}

// The star's value with the mover where the mesh has it now: the minimum over its vertices of
// min(nodal step, target), or -inf when a tet leaves the bounds or is not positively oriented.
// k_sum / m_sum: scratch, the vertices' sums. Not `bounded`: the minimum over its vertices of
// the nodal step alone, whatever the tets (the gradient of the search directions, below).
double star_value(const TetMesh& mesh, const Star& s, const NodalRaiseOptions& o,
                  std::vector<double>& k_sum, std::vector<double>& m_sum, bool bounded = true) {
  k_sum = s.k_rest;
  m_sum = s.m_rest;
  for (std::size_t n = 0; n < s.tets.size(); ++n) {
    const int* v = tet_of(mesh, s.tets[n]);
    const double *a = mesh.point(v[0]), *b = mesh.point(v[1]), *c = mesh.point(v[2]),
                 *d = mesh.point(v[3]);
    if (bounded) {
      if (orient3d(a, b, c, d) <= 0) return -kInf;
      const std::array<double, 4> q = tet_table_qualities(a, b, c, d);
      if (q[0] < o.q_floor || q[2] < o.angle_floor || q[3] > s.ceiling[n]) return -kInf;
      if (o.dt_floor > 0 && tet_time_step(a, b, c, d) < o.dt_floor) return -kInf;
    }
    double k[4], m;
    tet_vertex_terms(a, b, c, d, k, &m);
    for (int j = 0; j < 4; ++j) {
      const std::size_t i = std::find(s.verts.begin(), s.verts.end(), v[j]) - s.verts.begin();
      k_sum[i] += k[j];
      m_sum[i] += m;
    }
  }
  double value = bounded ? o.target : kInf;
  for (std::size_t i = 0; i < s.verts.size(); ++i)
    if (k_sum[i] > 0 && m_sum[i] > 0) value = std::min(value, 2.0 / std::sqrt(k_sum[i] / m_sum[i]));
  return value;
}

// How far each tet of the star is inside each of its bounds (4 per tet, in the star's order): Q -
// q_floor, the minimum dihedral angle's distance to angle_floor and the maximum's to its ceiling
// (in units of 60 degrees), the element step's relative distance to dt_floor (+inf without one).
void star_margins(const TetMesh& mesh, const Star& s, const NodalRaiseOptions& o,
                  std::vector<double>& margins) {
  margins.resize(4 * s.tets.size());
  for (std::size_t n = 0; n < s.tets.size(); ++n) {
    const int* v = tet_of(mesh, s.tets[n]);
    const double *a = mesh.point(v[0]), *b = mesh.point(v[1]), *c = mesh.point(v[2]),
                 *d = mesh.point(v[3]);
    const std::array<double, 4> q = tet_table_qualities(a, b, c, d);
    margins[4 * n] = q[0] - o.q_floor;
    margins[4 * n + 1] = (q[2] - o.angle_floor) / 60;
    margins[4 * n + 2] = (s.ceiling[n] - q[3]) / 60;
    margins[4 * n + 3] = o.dt_floor > 0 ? tet_time_step(a, b, c, d) / o.dt_floor - 1 : kInf;
  }
}

// Where the fixed directions all fail because the star sits on its bounds (igl_cheburashka: an
// interior vertex whose four flat tets are each at its own maximum dihedral angle; the way up for
// the low vertex is a narrow cone between the axes), the directions of the gradient: g, the
// central differences (step h) of the unbounded value over the mover's position, and g with its
// components against the bounds nearly reached taken out (cyclic projections on the half-spaces
// where none of them decreases), alone and tilted towards the inside of those bounds. None where
// g vanishes. For an interior mover.
std::vector<Vec3> gradient_directions(TetMesh& mesh, const Star& s, const NodalRaiseOptions& o,
                                      int w, double h, std::vector<double>& k_sum,
                                      std::vector<double>& m_sum) {
  double* P = mesh.point(w);
  const Vec3 here = vec3(P);
  std::vector<double> margin, plus, minus;
  star_margins(mesh, s, o, margin);
  Vec3 g{0, 0, 0};
  std::vector<Vec3> c(margin.size(), Vec3{0, 0, 0});
  for (int k = 0; k < 3; ++k) {
    double f[2];
    for (int side = 0; side < 2; ++side) {
      for (int j = 0; j < 3; ++j) P[j] = here[j];
      P[k] += side ? -h : h;
      f[side] = star_value(mesh, s, o, k_sum, m_sum, false);
      star_margins(mesh, s, o, side ? minus : plus);
    }
    g[k] = (f[0] - f[1]) / (2 * h);
    for (std::size_t i = 0; i < margin.size(); ++i) c[i][k] = (plus[i] - minus[i]) / (2 * h);
  }
  for (int j = 0; j < 3; ++j) P[j] = here[j];
  std::vector<Vec3> d;
  if (!(norm(g) > 0) || !std::isfinite(norm(g))) return d;
  d.push_back((1 / norm(g)) * g);
  // The bounds a step of a few h would reach.
  std::vector<Vec3> active;
  for (std::size_t i = 0; i < margin.size(); ++i) {
    const Vec3& ci = c[i];
    if (std::isfinite(margin[i]) && std::isfinite(norm(ci)) && norm(ci) > 0 &&
        margin[i] < 4 * h * norm(ci))
      active.push_back((1 / norm(ci)) * ci);
  }
  if (active.empty()) return d;
  Vec3 along = g;
  for (int round = 0; round < 50; ++round) {
    bool inside = true;
    for (const Vec3& a : active) {
      const double x = dot(along, a);
      if (x < 0) {
        along = along - x * a;
        inside = false;
      }
    }
    if (inside) break;
  }
  if (!(norm(along) > 1e-9 * norm(g)) || !(dot(along, g) > 0)) return d;
  const Vec3 u = (1 / norm(along)) * along;
  d.push_back(u);
  Vec3 in{0, 0, 0};
  for (const Vec3& a : active) in = in + a;
  const Vec3 tilted = u + (norm(in) > 0 ? (0.25 / norm(in)) : 0.0) * in;
  if (norm(tilted) > 0) d.push_back((1 / norm(tilted)) * tilted);
  return d;
}

}  // namespace

NodalRaiseStats raise_nodal_steps(TetMesh& mesh, const BoundaryModel& model,
                                  const NodalRaiseOptions& o) {
  NodalRaiseStats stats;
  VertexTimeSteps steps = vertex_time_steps(mesh);
  const int nv = mesh.nb_vertices();
  double lowest = kInf;
  std::vector<std::pair<double, int>> low;
  for (int v = 0; v < nv; ++v) {
    lowest = std::min(lowest, steps.dt(v));
    if (steps.dt(v) < o.target) low.push_back({steps.dt(v), v});
  }
  stats.min_before = stats.min_after = lowest;
  stats.nb_low = static_cast<long>(low.size());
  if (low.empty()) return stats;
  const VertexTets vt = vertex_tets(mesh);
  const BoundaryFans fans = model.geometry ? boundary_fans(mesh) : BoundaryFans{};
  std::vector<double> k_sum, m_sum;
  PatternMoveOptions search = o.search;
  search.stop_at = o.target;
  for (int pass = 0; pass < o.passes && !low.empty(); ++pass) {
    std::sort(low.begin(), low.end());
    if (static_cast<int>(low.size()) > o.max_vertices) low.resize(o.max_vertices);
    long moved_this_pass = 0;
    for (const auto& [unused, v] : low) {
      if (!(steps.dt(v) < o.target)) continue;  // raised by an earlier vertex's moves
      // The movers: v and the vertices sharing a tet with it, in increasing order.
      std::vector<int> movers;
      for (const int* t = vt.begin_of(v); t != vt.end_of(v); ++t)
        for (int k = 0; k < 4; ++k) movers.push_back(tet_of(mesh, *t)[k]);
      std::sort(movers.begin(), movers.end());
      movers.erase(std::unique(movers.begin(), movers.end()), movers.end());
      for (int w : movers) {
        if (!may_move(mesh, model, w)) continue;
        const Star s = star_of(mesh, vt, steps, w, o);
        search.extra_directions = nullptr;
        if (o.gradient_directions)
          search.extra_directions = [&](double h) {
            return gradient_directions(mesh, s, o, w, h, k_sum, m_sum);
          };
        if (!pattern_move(
                mesh, model, vt, fans, w, [&] { return star_value(mesh, s, o, k_sum, m_sum); },
                search))
          continue;
        ++stats.nb_moved;
        ++moved_this_pass;
        // The sums of the star's vertices at the new position.
        star_value(mesh, s, o, k_sum, m_sum);
        for (std::size_t i = 0; i < s.verts.size(); ++i) {
          steps.kdiag[s.verts[i]] = k_sum[i];
          steps.mass[s.verts[i]] = m_sum[i];
        }
      }
    }
    if (moved_this_pass == 0) break;
    low.clear();
    for (int v = 0; v < nv; ++v)
      if (steps.dt(v) < o.target) low.push_back({steps.dt(v), v});
  }
  stats.min_after = kInf;
  for (int v = 0; v < nv; ++v) stats.min_after = std::min(stats.min_after, steps.dt(v));
  return stats;
}

}  // namespace cvtmesh
