#include "core/cvt/voronoi_centroids2d.h"

#include <array>
#include <cstddef>
#include <type_traits>

#include "core/delaunay/cdt2d.h"
#include "core/geometry/tet_geometry.h"
#include "core/mesh/edge_index.h"

namespace cvtmesh {
namespace {

using Pt = std::array<double, 2>;

// Keeps the part of the convex polygon `poly` on the left of the directed line p -> q. A polygon
// wholly on the left is kept as it is (what the clip would rebuild, vertex for vertex).
void clip_left(std::vector<Pt>& poly, const double* p, const double* q, std::vector<Pt>& tmp,
               std::vector<double>& f) {
  const std::size_t n = poly.size();
  if (n == 0) return;
  const double dx = q[0] - p[0], dy = q[1] - p[1];
  f.resize(n);
  bool all_left = true;
  for (std::size_t i = 0; i < n; ++i) {
    f[i] = dx * (poly[i][1] - p[1]) - dy * (poly[i][0] - p[0]);
    all_left = all_left && f[i] >= 0;
  }
  if (all_left) return;
  tmp.clear();
  double fa = f[n - 1];
  for (std::size_t i = 0, prev = n - 1; i < n; prev = i++) {
    const Pt& a = poly[prev];
    const Pt& b = poly[i];
    const double fb = f[i];
    if ((fa >= 0) != (fb >= 0)) {
      const double s = fa / (fa - fb);
      tmp.push_back({a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])});
    }
    if (fb >= 0) tmp.push_back(b);
    fa = fb;
  }
  poly.swap(tmp);
}

// Dunavant's 6-point rule, exact for degree 4: barycentric (a, b, b) permutations.
constexpr double kW1 = 0.223381589678011, kA1 = 0.108103018168070, kB1 = 0.445948490915965;
constexpr double kW2 = 0.109951743655322, kA2 = 0.816847572980459, kB2 = 0.091576213509771;

struct Acc {
  double mass = 0, mx = 0, my = 0, energy = 0;
};

// Adds the integrals over the convex polygon `poly` (counter-clockwise) around generator z;
// density: a callable double(const double* x), or nullptr for rho = 1 (exact integrals).
template <class Density>
void integrate(const std::vector<Pt>& poly, const double* z, Density& density, Acc& acc) {
  for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
    const Pt& a = poly[0];
    const Pt& b = poly[k];
    const Pt& c = poly[k + 1];
    const double area = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    if (!(area > 0)) continue;
    if constexpr (std::is_same_v<Density, std::nullptr_t>) {
      const double g[2] = {(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3};
      auto d2 = [](const double* u, const double* v) {
        return (u[0] - v[0]) * (u[0] - v[0]) + (u[1] - v[1]) * (u[1] - v[1]);
      };
      acc.mass += area;
      acc.mx += area * g[0];
      acc.my += area * g[1];
      acc.energy += area * (d2(g, z) + (d2(a.data(), g) + d2(b.data(), g) + d2(c.data(), g)) / 12);
    } else {
      static constexpr double kBary[6][3] = {{kA1, kB1, kB1}, {kB1, kA1, kB1}, {kB1, kB1, kA1},
                                             {kA2, kB2, kB2}, {kB2, kA2, kB2}, {kB2, kB2, kA2}};
      for (int q = 0; q < 6; ++q) {
        const double w = area * (q < 3 ? kW1 : kW2);
        const double x[2] = {kBary[q][0] * a[0] + kBary[q][1] * b[0] + kBary[q][2] * c[0],
                             kBary[q][0] * a[1] + kBary[q][1] * b[1] + kBary[q][2] * c[1]};
        const double wr = w * density(x);
        acc.mass += wr;
        acc.mx += wr * x[0];
        acc.my += wr * x[1];
        acc.energy += wr * ((x[0] - z[0]) * (x[0] - z[0]) + (x[1] - z[1]) * (x[1] - z[1]));
      }
    }
  }
}

// make_density(): a thread's density callable (integrate's Density), made once per thread.
template <class MakeDensity>
std::vector<VoronoiCell2d> centroids(const TriMesh2& mesh, bool parallel,
                                     const Cdt2dResult* delaunay, const MakeDensity& make_density) {
  const int nv = mesh.nb_vertices(), nt = mesh.nb_tris();
  std::vector<VoronoiCell2d> cells(nv);

  // Voronoi regions: the circumcentres of the Delaunay triangles around each vertex, in
  // counter-clockwise order (every input vertex is interior to the super-triangle).
  Cdt2dResult own;
  if (!delaunay || delaunay->tris.empty()) own = cdt2d(mesh.xy, {});
  const Cdt2dResult& dt = delaunay && !delaunay->tris.empty() ? *delaunay : own;
  const int ndt = static_cast<int>(dt.tris.size() / 3);
  std::vector<Pt> cc(ndt);
  for (int t = 0; t < ndt; ++t)
    cc[t] = tri_circumcenter2d(&dt.xy[2 * dt.tris[3 * t]], &dt.xy[2 * dt.tris[3 * t + 1]],
                               &dt.xy[2 * dt.tris[3 * t + 2]]);
  std::vector<int> dt_vtri(nv + 3, -1);
  for (int t = 0; t < ndt; ++t)
    for (int k = 0; k < 3; ++k) dt_vtri[dt.tris[3 * t + k]] = t;

  // Mesh: which slots are constrained.
  std::vector<char> cons(3 * static_cast<std::size_t>(nt), 0);
  {
    const EdgeIndex ce(mesh.edges, nv);
    for (int t = 0; t < nt; ++t) {
      const int* tv = &mesh.tris[3 * t];
      if (tv[0] < 0) continue;
      for (int k = 0; k < 3; ++k) cons[3 * t + k] = ce.contains(tv[(k + 1) % 3], tv[(k + 2) % 3]);
    }
  }
  // Triangles around each vertex (seeds of the search): CSR.
  std::vector<int> start(nv + 1, 0), around;
  for (int t = 0; t < nt; ++t)
    if (mesh.tris[3 * t] >= 0)
      for (int k = 0; k < 3; ++k) ++start[mesh.tris[3 * t + k] + 1];
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  around.resize(start[nv]);
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int t = 0; t < nt; ++t)
      if (mesh.tris[3 * t] >= 0)
        for (int k = 0; k < 3; ++k) around[fill[mesh.tris[3 * t + k]]++] = t;
  }

  // One cell: its buffers are the caller's (one set per thread); stamp[t] == i marks triangle t
  // as reached for cell i.
  struct Buffers {
    std::vector<int> stamp, queue;
    std::vector<Pt> region, piece, tmp;
    std::vector<double> side;
  };
  auto cell = [&](int i, Buffers& B, auto& density) {
    std::vector<int>& stamp = B.stamp;
    std::vector<int>& queue = B.queue;
    std::vector<Pt>& region = B.region;
    std::vector<Pt>& piece = B.piece;
    std::vector<Pt>& tmp = B.tmp;
    const double* z = mesh.point(i);
    if (start[i] == start[i + 1]) {  // not used by any triangle: an empty cell
      cells[i].centroid[0] = z[0], cells[i].centroid[1] = z[1];
      return;
    }
    // Voronoi region of i.
    region.clear();
    const int t0 = dt_vtri[i];
    int t = t0;
    do {
      region.push_back(cc[t]);
      int k = 0;
      while (dt.tris[3 * t + k] != i) ++k;
      t = dt.adj[3 * t + (k + 1) % 3] / 3;
    } while (t != t0 && static_cast<int>(region.size()) <= ndt);
    // Breadth-first search over the mesh from the triangles around i.
    Acc acc;
    queue.clear();
    for (int k = start[i]; k < start[i + 1]; ++k)
      if (stamp[around[k]] != i) stamp[around[k]] = i, queue.push_back(around[k]);
    for (std::size_t qi = 0; qi < queue.size(); ++qi) {
      const int tt = queue[qi];
      const int* tv = &mesh.tris[3 * tt];
      piece = region;
      for (int k = 0; k < 3 && piece.size() >= 3; ++k)
        clip_left(piece, mesh.point(tv[k]), mesh.point(tv[(k + 1) % 3]), tmp, B.side);
      if (piece.size() < 3) continue;
      integrate(piece, z, density, acc);
      for (int k = 0; k < 3; ++k) {
        const int o = mesh.adj[3 * tt + k];
        if (o < 0 || cons[3 * tt + k] || stamp[o / 3] == i) continue;
        stamp[o / 3] = i;
        queue.push_back(o / 3);
      }
    }
    VoronoiCell2d& c = cells[i];
    c.mass = acc.mass;
    c.energy = acc.energy;
    if (acc.mass > 0) {
      c.centroid[0] = acc.mx / acc.mass;
      c.centroid[1] = acc.my / acc.mass;
    } else {
      c.centroid[0] = z[0], c.centroid[1] = z[1];
    }
  };
  // The cells in the order in which their vertices first appear in the triangles (the
  // rebuilt mesh's triangles follow the Delaunay insertion's Hilbert order): consecutive cells
  // are neighbours and share the data they read. Each cell is computed alone, so the order
  // changes no result; the vertices of no triangle come last.
  std::vector<int> order;
  order.reserve(nv);
  {
    std::vector<char> seen(nv, 0);
    for (int t = 0; t < nt; ++t)
      if (mesh.tris[3 * t] >= 0)
        for (int k = 0; k < 3; ++k) {
          const int v = mesh.tris[3 * t + k];
          if (!seen[v]) seen[v] = 1, order.push_back(v);
        }
    for (int v = 0; v < nv; ++v)
      if (!seen[v]) order.push_back(v);
  }
  if (!parallel) {
    Buffers B;
    B.stamp.assign(nt, -1);
    auto density = make_density();
    for (int i : order) cell(i, B, density);
    return cells;
  }
#pragma omp parallel
  {
    Buffers B;
    B.stamp.assign(nt, -1);
    auto density = make_density();
#pragma omp for schedule(static, 256)
    for (int k = 0; k < nv; ++k) cell(order[k], B, density);
  }
  return cells;
}

}  // namespace

std::vector<VoronoiCell2d> voronoi_centroids2d(const TriMesh2& mesh,
                                               const std::function<double(const double*)>& density,
                                               bool parallel, const Cdt2dResult* delaunay) {
  if (!density) return centroids(mesh, parallel, delaunay, [] { return nullptr; });
  return centroids(mesh, parallel, delaunay, [&density] { return std::cref(density); });
}

std::vector<VoronoiCell2d> voronoi_centroids2d(const TriMesh2& mesh, const SizingField2d& sizing,
                                               bool parallel, const Cdt2dResult* delaunay) {
  if (sizing.is_uniform()) return centroids(mesh, parallel, delaunay, [] { return nullptr; });
  // Each thread keeps its own walk's hint (the same sizes as sizing.density(x)).
  return centroids(mesh, parallel && sizing.thread_safe(), delaunay, [&sizing] {
    return [&sizing, hint = -1](const double* x) mutable {
      const double h = sizing.size(x, hint);
      return 1.0 / (h * h * h * h);
    };
  });
}

}  // namespace cvtmesh
