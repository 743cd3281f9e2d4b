#include "core/pipeline/perturb2d.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <unordered_set>
#include <vector>

#include "core/delaunay/cdt2d_locate.h"
#include "core/delaunay/cdt2d_remesh.h"
#include "core/geometry/tet_geometry.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/face_key.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

// Uniform double in [0, 1) from the generator's raw bits (same on every platform).
double uniform01(std::mt19937& g) {
  const std::uint64_t hi = g() >> 5, lo = g() >> 6;
  return (static_cast<double>(hi) * 67108864.0 + static_cast<double>(lo)) / 9007199254740992.0;
}

// The constrained edges as closed loops of directed edges (direction taken from the triangle on
// their left); returns, per loop, its signed area (> 0 for the outer boundary of a surface).
struct Loops {
  std::vector<std::vector<int>> loops;  // vertex sequences
  std::vector<double> area;
};

Loops boundary_loops(const TriMesh2& m) {
  std::unordered_set<EdgeKey, EdgeKeyHash> cons;
  for (int e = 0; e < m.nb_edges(); ++e) cons.insert(edge_key(m.edges[2 * e], m.edges[2 * e + 1]));
  // Directed boundary edges (u -> v) with the domain on the left: edges of triangles with no
  // neighbour across them.
  std::vector<int> next(m.nb_vertices(), -1);
  for (int t = 0; t < m.nb_tris(); ++t) {
    const int* tv = &m.tris[3 * t];
    if (tv[0] < 0) continue;
    for (int k = 0; k < 3; ++k)
      if (m.adj[3 * t + k] < 0) next[tv[(k + 1) % 3]] = tv[(k + 2) % 3];
  }
  Loops L;
  std::vector<char> seen(m.nb_vertices(), 0);
  for (int v = 0; v < m.nb_vertices(); ++v) {
    if (next[v] < 0 || seen[v]) continue;
    std::vector<int> loop;
    for (int u = v; u >= 0 && !seen[u]; u = next[u]) {
      seen[u] = 1;
      loop.push_back(u);
    }
    double a = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const double* p = m.point(loop[i]);
      const double* q = m.point(loop[(i + 1) % loop.size()]);
      a += 0.5 * (p[0] * q[1] - p[1] * q[0]);
    }
    L.loops.push_back(std::move(loop));
    L.area.push_back(a);
  }
  return L;
}

}  // namespace

Perturb2dResult perturb_2d(TriMesh2& mesh, const Perturb2dOptions& o) {
  if (mesh.adj.size() != mesh.tris.size()) build_adjacency2(mesh);
  const MeshCheck c = check_mesh(mesh);
  if (!c.ok)
    throw InputError("perturb: invalid input mesh: " +
                     (c.problems.empty() ? std::string() : c.problems[0]));
  const bool random = o.kind == Perturbation2d::kRandom;
  const double amount = o.amount >= 0 ? o.amount : (random ? 0.4 : 0.5);
  if (!random && amount > 1)
    throw std::invalid_argument("perturb: --amount for --cluster must be in [0, 1]");
  Perturb2dResult r;
  const int nv = mesh.nb_vertices(), nt = mesh.nb_tris();

  std::vector<char> on_edge(nv, 0);
  for (int v : mesh.edges) on_edge[v] = 1;
  std::vector<int> free;
  for (int v = 0; v < nv; ++v)
    if (mesh.vclass[v].dim == 2 && !on_edge[v]) free.push_back(v);

  // Local edge length, a triangle at each vertex, constrained slots.
  std::vector<double> hsum(nv, 0);
  std::vector<int> hcnt(nv, 0), vtri(nv, -1);
  std::unordered_set<EdgeKey, EdgeKeyHash> ce;
  for (int e = 0; e < mesh.nb_edges(); ++e)
    ce.insert(edge_key(mesh.edges[2 * e], mesh.edges[2 * e + 1]));
  std::vector<char> stop(3 * static_cast<std::size_t>(nt), 0);
  double centre[2] = {0, 0}, area = 0;
  for (int t = 0; t < nt; ++t) {
    const int* tv = &mesh.tris[3 * t];
    if (tv[0] < 0) continue;
    const double a = tri_area2d(mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]));
    area += a;
    for (int k = 0; k < 3; ++k) {
      const int u = tv[k], w = tv[(k + 1) % 3];
      const double l =
          std::hypot(mesh.point(u)[0] - mesh.point(w)[0], mesh.point(u)[1] - mesh.point(w)[1]);
      hsum[u] += l, hsum[w] += l, ++hcnt[u], ++hcnt[w];
      vtri[u] = t;
      stop[3 * t + k] = ce.count(edge_key(tv[(k + 1) % 3], tv[(k + 2) % 3])) ? 1 : 0;
      centre[0] += a * mesh.point(u)[0] / 3;
      centre[1] += a * mesh.point(u)[1] / 3;
    }
  }
  if (area > 0) centre[0] /= area, centre[1] /= area;

  // Cluster attractor.
  std::vector<std::array<int, 2>> hole_edges;
  if (!random) {
    const Loops loops = boundary_loops(mesh);
    int outer = -1;
    for (std::size_t i = 0; i < loops.loops.size(); ++i)
      if (outer < 0 || loops.area[i] > loops.area[outer]) outer = static_cast<int>(i);
    for (std::size_t i = 0; i < loops.loops.size(); ++i)
      if (static_cast<int>(i) != outer && loops.area[i] < 0)
        for (std::size_t k = 0; k < loops.loops[i].size(); ++k)
          hole_edges.push_back(
              {loops.loops[i][k], loops.loops[i][(k + 1) % loops.loops[i].size()]});
    if (o.attractor == "auto")
      r.attractor = hole_edges.empty() ? "centre" : "hole";
    else if (o.attractor == "centre" || o.attractor == "center")
      r.attractor = "centre";
    else if (o.attractor == "hole")
      r.attractor = "hole";
    else
      throw std::invalid_argument("perturb: unknown attractor \"" + o.attractor +
                                  "\" (auto, centre, hole)");
    if (r.attractor == "hole" && hole_edges.empty())
      throw std::invalid_argument("perturb: attractor \"hole\" but the domain has no hole");
  }

  std::mt19937 rng(o.seed);
  std::vector<double> target(2 * free.size());
  for (std::size_t k = 0; k < free.size(); ++k) {
    const int v = free[k];
    const double* z = mesh.point(v);
    double d[2] = {0, 0};
    if (random) {
      const double h = hcnt[v] ? hsum[v] / hcnt[v] : 0;
      // Uniform in the disk of radius amount * h (always draw both numbers: reproducible).
      const double rad = amount * h * std::sqrt(uniform01(rng));
      const double ang = 2 * M_PI * uniform01(rng);
      d[0] = rad * std::cos(ang), d[1] = rad * std::sin(ang);
    } else {
      double a[2] = {centre[0], centre[1]};
      if (r.attractor == "hole") {
        double best = std::numeric_limits<double>::infinity();
        for (const auto& e : hole_edges) {
          const double* p = mesh.point(e[0]);
          const double* q = mesh.point(e[1]);
          const double ex = q[0] - p[0], ey = q[1] - p[1];
          const double l2 = ex * ex + ey * ey;
          double s = l2 > 0 ? ((z[0] - p[0]) * ex + (z[1] - p[1]) * ey) / l2 : 0;
          s = std::clamp(s, 0.0, 1.0);
          const double x = p[0] + s * ex, y = p[1] + s * ey;
          const double dd = (x - z[0]) * (x - z[0]) + (y - z[1]) * (y - z[1]);
          if (dd < best) best = dd, a[0] = x, a[1] = y;
        }
      }
      d[0] = amount * (a[0] - z[0]), d[1] = amount * (a[1] - z[1]);
    }
    double f = 1;
    bool ok = false;
    for (int halving = 0; halving <= 10; ++halving, f *= 0.5) {
      const double p[2] = {z[0] + f * d[0], z[1] + f * d[1]};
      const Locate2dResult loc = locate2d(mesh, p, vtri[v], stop);
      if (loc.tri >= 0 && (loc.on_vertex < 0 || loc.on_vertex == v) &&
          (loc.on_edge < 0 || !stop[3 * loc.tri + loc.on_edge])) {
        ok = true;
        break;
      }
    }
    if (!ok) f = 0;
    if (f < 1) ++r.nb_limited;
    if (f > 0 && (d[0] != 0 || d[1] != 0)) ++r.nb_moved;
    target[2 * k] = z[0] + f * d[0];
    target[2 * k + 1] = z[1] + f * d[1];
  }
  for (std::size_t k = 0; k < free.size(); ++k) {
    double* z = mesh.point(free[k]);
    z[0] = target[2 * k], z[1] = target[2 * k + 1];
  }
  cdt2d_remesh(mesh);
  const MeshCheck after = check_mesh(mesh);
  if (!after.ok)
    throw InvariantError("perturb: invalid mesh after re-triangulation: " +
                         (after.problems.empty() ? std::string() : after.problems[0]));
  return r;
}

}  // namespace cvtmesh
