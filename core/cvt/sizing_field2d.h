// The sizing field H of a planar mesh (target edge length at a point) and the CVT density
// rho = 1/H^(d+2) = 1/H^4 derived from it (Du & Wang, Algorithm 2.1, step 1).
#pragma once
#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "core/mesh/tri_mesh2.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace cvtmesh {

struct SizingField2dOptions {
  // "uniform": H = h everywhere (rho = 1); "function": H = function(x); "mesh": the local edge
  // length of a background mesh (at each vertex the mean length of its edges), interpolated
  // linearly (P1) on the background triangles.
  std::string kind = "mesh";
  double h = 0;  // "uniform": the size; 0 = the mean length of the mesh's constrained edges
  std::function<double(const double* x)> function;  // "function": x = (x, y); must be > 0
  // "mesh": the background mesh; nullptr = the mesh given to the constructor (as it is then).
  const TriMesh2* background = nullptr;
  // "mesh": Jacobi passes smoothing the background's vertex sizes (0: none); the vertices on
  // constrained edges then take their constrained edges' mean length.
  int smoothing_passes = 0;
};

class SizingField2d {
 public:
  // Throws std::invalid_argument for an unknown kind or a missing function, InputError for a
  // mesh without triangles.
  SizingField2d(const TriMesh2& mesh, const SizingField2dOptions& options);

  // H(x) > 0 at x = (x, y). Throws InputError if a user function returns a non-positive value.
  double size(const double* x) const;
  // size(x) for a caller that keeps its own hint (a background triangle id: -1 at first, then
  // updated by each call) instead of the thread's: "mesh" walks from the triangle of the
  // caller's last point. The value is size(x)'s (the triangle that strictly contains x, which
  // every walk reaches, or the bucket scan's, which does not depend on the hint).
  double size(const double* x, int& hint) const {
    if (kind_ == Kind::kMesh && hint >= 0) {
      int t = hint;
      for (int step = 0; step < 8 && t >= 0; ++step) {
        double l[3];
        if (!barycentric(t, x, l)) break;
        if (l[0] > 0 && l[1] > 0 && l[2] > 0) {
          hint = t;
          return interpolate(t, l);
        }
        const int k = l[0] <= l[1] && l[0] <= l[2] ? 0 : l[1] <= l[2] ? 1 : 2;
        t = bg_[t].adj[k];
      }
    }
    return size_scan(x, hint);
  }
  // rho(x) = 1 / H(x)^4.
  double density(const double* x) const {
    const double h = size(x);
    return 1.0 / (h * h * h * h);
  }
  // True for "uniform" (rho is constant: integrals can be exact).
  bool is_uniform() const { return kind_ == Kind::kUniform; }
  // size() may be called from several threads at once (not so for a user's size function).
  bool thread_safe() const { return kind_ != Kind::kFunction; }

 private:
  enum class Kind { kUniform, kFunction, kMesh };
  Kind kind_ = Kind::kUniform;
  double h_ = 1;
  std::function<double(const double*)> function_;
  // Background mesh ("mesh"): per triangle, what size() reads, in one record (one or two cache
  // lines instead of six scattered reads): its first corner a, its edges b - a and c - a, their
  // determinant, its corners' sizes and its neighbours (across the edge opposite corner k);
  // and the bucket grid of triangles.
  struct BgTri {
    double a[2], e1[2], e2[2], det;
    double h[3];
    int adj[3];
  };
  std::vector<BgTri> bg_;
  // Barycentric coordinates of x in background triangle t (false if it is flat), and the P1
  // size there (the coordinates clamped at 0 and renormalised).
  bool barycentric(int t, const double* x, double l[3]) const {
    const BgTri& g = bg_[t];
    if (g.det == 0) return false;
    const double dx = x[0] - g.a[0], dy = x[1] - g.a[1];
#if defined(__SSE2__)
    // Both quotients by one packed division (each lane the IEEE quotient, as two divisions).
    alignas(16) double q[2];
    _mm_store_pd(q, _mm_div_pd(_mm_set_pd(g.e1[0] * dy - g.e1[1] * dx, dx * g.e2[1] - dy * g.e2[0]),
                               _mm_set1_pd(g.det)));
    l[1] = q[0], l[2] = q[1];
#else
    l[1] = (dx * g.e2[1] - dy * g.e2[0]) / g.det;
    l[2] = (g.e1[0] * dy - g.e1[1] * dx) / g.det;
#endif
    l[0] = 1 - l[1] - l[2];
    return true;
  }
  double interpolate(int t, const double l[3]) const {
    const double* h = bg_[t].h;
    const double l0 = std::max(l[0], 0.0), l1 = std::max(l[1], 0.0), l2 = std::max(l[2], 0.0);
    const double s = l0 + l1 + l2;
    return (l0 * h[0] + l1 * h[1] + l2 * h[2]) / s;
  }
  // size(x, hint) past the walk: the uniform size, the user's function, or the bucket scan.
  double size_scan(const double* x, int& hint) const;
  double lo_[2] = {0, 0}, cell_[2] = {1, 1};
  int nx_ = 1, ny_ = 1;
  std::vector<int> bucket_start_, bucket_tris_;
};

}  // namespace cvtmesh
