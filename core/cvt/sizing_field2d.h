// The sizing field H of a planar mesh (target edge length at a point) and the CVT density
// rho = 1/H^(d+2) = 1/H^4 derived from it (Du & Wang, Algorithm 2.1, step 1).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "core/mesh/tri_mesh2.h"

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
  // Background mesh ("mesh"): coordinates, triangles, vertex sizes, bucket grid of triangles.
  std::vector<double> bg_xy_;
  std::vector<int> bg_tris_;
  std::vector<double> bg_h_;
  std::vector<int> bg_adj_;  // 3 per triangle: the neighbour across the edge opposite corner k
  double lo_[2] = {0, 0}, cell_[2] = {1, 1};
  int nx_ = 1, ny_ = 1;
  std::vector<int> bucket_start_, bucket_tris_;
};

}  // namespace cvtmesh
