#include "core/mesh/find_surface_intersections.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <omp.h>

#include "core/geometry/predicates.h"

namespace cvtmesh {
namespace {

int sign(double x) {
  return (x > 0) - (x < 0);
}

// Coordinates of p dropped along `axis` (a projection onto a coordinate plane).
struct P2 {
  double v[2];
};
P2 project(const double* p, int axis) {
  return axis == 0 ? P2{{p[1], p[2]}} : axis == 1 ? P2{{p[2], p[0]}} : P2{{p[0], p[1]}};
}
int o2(const P2& a, const P2& b, const P2& c) {
  return sign(orient2d(a.v, b.v, c.v));
}

// Closed segments pq and ab of a plane intersect.
bool segments_meet_2d(const P2& p, const P2& q, const P2& a, const P2& b) {
  const int s1 = o2(p, q, a), s2 = o2(p, q, b), s3 = o2(a, b, p), s4 = o2(a, b, q);
  if (s1 * s2 > 0 || s3 * s4 > 0) return false;
  if (s1 != 0 || s2 != 0) return true;
  // Collinear: overlap of the projections on the line.
  auto within = [](const P2& x, const P2& y, const P2& z) {  // z in the box of xy
    for (int d = 0; d < 2; ++d)
      if (z.v[d] < std::min(x.v[d], y.v[d]) || z.v[d] > std::max(x.v[d], y.v[d])) return false;
    return true;
  };
  return within(p, q, a) || within(p, q, b) || within(a, b, p) || within(a, b, q);
}

// Closed point p in the closed triangle abc (same plane, 2D).
bool point_in_triangle_2d(const P2& p, const P2& a, const P2& b, const P2& c) {
  const int s1 = o2(a, b, p), s2 = o2(b, c, p), s3 = o2(c, a, p);
  return !((s1 < 0 || s2 < 0 || s3 < 0) && (s1 > 0 || s2 > 0 || s3 > 0));
}

int dominant_axis(const double* a, const double* b, const double* c) {
  double u[3], w[3];
  for (int d = 0; d < 3; ++d) {
    u[d] = b[d] - a[d];
    w[d] = c[d] - a[d];
  }
  const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                       u[0] * w[1] - u[1] * w[0]};
  int axis = 0;
  for (int d = 1; d < 3; ++d)
    if (std::abs(n[d]) > std::abs(n[axis])) axis = d;
  return axis;
}

// Closed segment pq meets the closed triangle abc.
bool segment_meets_triangle(const double* p, const double* q, const double* a, const double* b,
                            const double* c) {
  const int sp = sign(orient3d(a, b, c, p)), sq = sign(orient3d(a, b, c, q));
  if (sp * sq > 0) return false;
  if (sp == 0 && sq == 0) {  // coplanar
    const int axis = dominant_axis(a, b, c);
    const P2 P = project(p, axis), Q = project(q, axis), A = project(a, axis), B = project(b, axis),
             C = project(c, axis);
    return point_in_triangle_2d(P, A, B, C) || point_in_triangle_2d(Q, A, B, C) ||
           segments_meet_2d(P, Q, A, B) || segments_meet_2d(P, Q, B, C) ||
           segments_meet_2d(P, Q, C, A);
  }
  const int s1 = sign(orient3d(p, q, a, b)), s2 = sign(orient3d(p, q, b, c)),
            s3 = sign(orient3d(p, q, c, a));
  return !((s1 < 0 || s2 < 0 || s3 < 0) && (s1 > 0 || s2 > 0 || s3 > 0));
}

// Triangles f = (f0,f1,f2) and g intersect other than in what they share.
bool improper(const std::vector<double>& xyz, const int* f, const int* g) {
  auto P = [&](int v) { return &xyz[3 * static_cast<std::size_t>(v)]; };
  int shared = 0, fs[3] = {0, 0, 0}, gs[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (f[i] == g[j]) {
        ++shared;
        fs[i] = gs[j] = 1;
      }
  if (shared == 3) return true;  // the same triangle twice
  if (shared == 2) {
    // They share an edge: improper only if folded onto each other (coplanar, same side).
    int fo = 0, go = 0;
    while (fs[fo]) ++fo;
    while (gs[go]) ++go;
    int e[2], k = 0;
    for (int i = 0; i < 3; ++i)
      if (fs[i]) e[k++] = f[i];
    if (orient3d(P(e[0]), P(e[1]), P(f[fo]), P(g[go])) != 0) return false;
    const int axis = dominant_axis(P(f[0]), P(f[1]), P(f[2]));
    const P2 A = project(P(e[0]), axis), B = project(P(e[1]), axis), X = project(P(f[fo]), axis),
             Y = project(P(g[go]), axis);
    return o2(A, B, X) * o2(A, B, Y) > 0;
  }
  if (shared == 1) {
    // (s,a,b) and (s,c,d): the edge opposite s in one meets the other.
    int fa[2], ga[2], k = 0, l = 0;
    for (int i = 0; i < 3; ++i) {
      if (!fs[i]) fa[k++] = f[i];
      if (!gs[i]) ga[l++] = g[i];
    }
    return segment_meets_triangle(P(fa[0]), P(fa[1]), P(g[0]), P(g[1]), P(g[2])) ||
           segment_meets_triangle(P(ga[0]), P(ga[1]), P(f[0]), P(f[1]), P(f[2]));
  }
  for (int i = 0; i < 3; ++i) {
    if (segment_meets_triangle(P(f[i]), P(f[(i + 1) % 3]), P(g[0]), P(g[1]), P(g[2]))) return true;
    if (segment_meets_triangle(P(g[i]), P(g[(i + 1) % 3]), P(f[0]), P(f[1]), P(f[2]))) return true;
  }
  return false;
}

}  // namespace

std::vector<std::array<int, 2>> find_surface_intersections(const std::vector<double>& xyz,
                                                           const std::vector<int>& tris,
                                                           int max_pairs) {
  std::vector<std::array<int, 2>> pairs;
  const int nf = static_cast<int>(tris.size() / 3);
  if (nf < 2) return pairs;
  std::vector<double> box(6 * static_cast<std::size_t>(nf));
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, size = 0, mean = 0;
  for (int f = 0; f < nf; ++f) {
    double* b = &box[6 * static_cast<std::size_t>(f)];
    for (int d = 0; d < 3; ++d) {
      b[d] = HUGE_VAL;
      b[3 + d] = -HUGE_VAL;
    }
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) {
        const double x = xyz[3 * static_cast<std::size_t>(tris[3 * f + k]) + d];
        b[d] = std::min(b[d], x);
        b[3 + d] = std::max(b[3 + d], x);
      }
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], b[d]);
      size = std::max(size, b[3 + d] - b[d]);
      mean += (b[3 + d] - b[d]) / (3.0 * nf);
    }
  }
  // Uniform grid, cells of twice the mean extent (a large triangle spans at most ~33^3 cells).
  double cell = std::max(2 * mean, size / 32);
  if (!(cell > 0)) cell = 1.0;
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return static_cast<std::uint64_t>(i * 73856093) ^ static_cast<std::uint64_t>(j * 19349663) ^
           static_cast<std::uint64_t>(k * 83492791);
  };
  auto idx = [&](double x, int d) {
    return static_cast<std::int64_t>(std::floor((x - lo[d]) / cell));
  };
  std::unordered_map<std::uint64_t, std::vector<int>> grid;
  for (int f = 0; f < nf; ++f) {
    const double* b = &box[6 * static_cast<std::size_t>(f)];
    for (std::int64_t i = idx(b[0], 0); i <= idx(b[3], 0); ++i)
      for (std::int64_t j = idx(b[1], 1); j <= idx(b[4], 1); ++j)
        for (std::int64_t k = idx(b[2], 2); k <= idx(b[5], 2); ++k) grid[key(i, j, k)].push_back(f);
  }
  // The pairs (f, g > f) of each triangle f, the triangles in chunks, those of a chunk in
  // parallel (each f by one thread, its `seen` marks that thread's); the chunk's pairs then taken
  // in f order while fewer than max_pairs are found before f: the pairs of the serial loop over f
  // that stops there, for any number of threads.
  constexpr int kChunk = 4096;
  std::vector<std::vector<int>> seen_of(
      static_cast<std::size_t>(std::max(1, omp_get_max_threads())));
  std::vector<std::vector<std::array<int, 2>>> of(static_cast<std::size_t>(std::min(nf, kChunk)));
  for (int begin = 0; begin < nf && static_cast<int>(pairs.size()) < max_pairs; begin += kChunk) {
    const int end = std::min(nf, begin + kChunk);
#pragma omp parallel for schedule(dynamic, 64) if (end - begin > 256)
    for (int f = begin; f < end; ++f) {
      std::vector<int>& seen = seen_of[static_cast<std::size_t>(omp_get_thread_num())];
      if (seen.empty()) seen.assign(static_cast<std::size_t>(nf), -1);
      std::vector<std::array<int, 2>>& mine = of[static_cast<std::size_t>(f - begin)];
      mine.clear();
      const double* b = &box[6 * static_cast<std::size_t>(f)];
      for (std::int64_t i = idx(b[0], 0); i <= idx(b[3], 0); ++i)
        for (std::int64_t j = idx(b[1], 1); j <= idx(b[4], 1); ++j)
          for (std::int64_t k = idx(b[2], 2); k <= idx(b[5], 2); ++k) {
            auto it = grid.find(key(i, j, k));
            if (it == grid.end()) continue;
            for (int g : it->second) {
              if (g <= f || seen[g] == f) continue;
              seen[g] = f;
              const double* c = &box[6 * static_cast<std::size_t>(g)];
              bool overlap = true;
              for (int d = 0; d < 3; ++d) overlap &= b[d] <= c[3 + d] && c[d] <= b[3 + d];
              if (overlap && improper(xyz, &tris[3 * f], &tris[3 * g])) mine.push_back({f, g});
            }
          }
    }
    for (int f = begin; f < end && static_cast<int>(pairs.size()) < max_pairs; ++f) {
      const auto& mine = of[static_cast<std::size_t>(f - begin)];
      pairs.insert(pairs.end(), mine.begin(), mine.end());
    }
  }
  std::sort(pairs.begin(), pairs.end());
  if (static_cast<int>(pairs.size()) > max_pairs) pairs.resize(max_pairs);
  return pairs;
}

}  // namespace cvtmesh
