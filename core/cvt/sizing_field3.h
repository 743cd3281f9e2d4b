// Sizing fields H(x) in 3D, with their gradient, for the CVT density rho = 1/H^5.
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "core/mesh/face_key.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

class SizingField3 {
 public:
  virtual ~SizingField3() = default;
  // H at x and its gradient g. `hint`: in/out cache of a location (a tet of a background mesh),
  // -1 if unknown.
  virtual double eval(const double* x, double g[3], int* hint) const = 0;
  // eval may be called from several threads at once (a user callback, e.g. a Python function,
  // may not).
  virtual bool thread_safe() const { return true; }
};

// H = h everywhere.
std::unique_ptr<SizingField3> make_uniform_sizing3(double h);
// H = f(x) (gradient by central differences with step `dx`).
std::unique_ptr<SizingField3> make_function_sizing3(std::function<double(const double*)> f,
                                                    double dx);
// H = the input mesh's local edge length: at each vertex the mean length of its edges,
// interpolated linearly on the (frozen) input mesh used as background mesh.
std::unique_ptr<SizingField3> make_mesh_sizing3(const TetMesh& background);

// The edges of the live tets, each once (sorted vertex pairs, sorted).
std::vector<EdgeKey> unique_edges(const TetMesh& mesh);

// Mean edge length of the mesh (each edge once).
double mean_edge_length(const TetMesh& mesh);

}  // namespace cvtmesh
