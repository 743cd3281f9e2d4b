// Mass centroids of the Voronoi cells of a planar mesh's vertices, clipped to the domain
// (Du & Wang, Algorithm 2.1, step 1), and the CVT energy F = sum_i int_{V_i} rho |x - z_i|^2.
#pragma once
#include <functional>
#include <vector>

#include "core/cvt/sizing_field2d.h"
#include "core/delaunay/cdt2d.h"
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

struct VoronoiCell2d {
  double mass = 0;              // int_{V_i} rho
  double centroid[2] = {0, 0};  // int rho x / mass (the generator itself if mass = 0)
  double energy = 0;            // int_{V_i} rho |x - z_i|^2
};

// mesh: a valid planar mesh (check_mesh ok); its triangles define the domain, its constrained
// edges (mesh.edges) the boundary and the interfaces between surfaces.
// For every vertex i (#V results, fixed vertices included) the cell V_i is its Voronoi region
// among all #V vertices, clipped to the domain: the part of it covered by the triangles reached
// from the triangles around i without crossing a constrained edge (so a cell never spills into
// another surface or across a hole). The Voronoi regions come from an unconstrained Delaunay
// triangulation of the vertices (cdt2d); each piece (region intersected with a mesh triangle)
// is a convex polygon. density == nullptr: rho = 1 and the integrals are exact; otherwise a
// degree-4 quadrature on each piece. parallel: the cells are computed by several threads
// (OpenMP), which may call density at the same time; the result is the same as serially.
// delaunay: cdt2d(mesh.xy, {}) if the caller has it (cdt2d_remesh gives it), else nullptr (or a
// result without triangles): computed here.
std::vector<VoronoiCell2d> voronoi_centroids2d(
    const TriMesh2& mesh, const std::function<double(const double*)>& density = nullptr,
    bool parallel = false, const Cdt2dResult* delaunay = nullptr);

// The same with rho = sizing.density(x) = 1 / H(x)^4 (sizing.is_uniform(): rho = 1, exact
// integrals), the sizes looked up by each thread's own walk (SizingField2d::size(x, hint)): no
// call through a std::function per quadrature point. parallel is ignored when the sizing is not
// thread_safe(). The same cells as voronoi_centroids2d(mesh, density) with that density.
std::vector<VoronoiCell2d> voronoi_centroids2d(const TriMesh2& mesh, const SizingField2d& sizing,
                                               bool parallel,
                                               const Cdt2dResult* delaunay = nullptr);

}  // namespace cvtmesh
