// Mass centroids of the Voronoi cells of a planar mesh's vertices, clipped to the domain
// (Du & Wang, Algorithm 2.1, step 1), and the CVT energy F = sum_i int_{V_i} rho |x - z_i|^2.
#pragma once
#include <functional>
#include <vector>

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
std::vector<VoronoiCell2d> voronoi_centroids2d(
    const TriMesh2& mesh, const std::function<double(const double*)>& density = nullptr,
    bool parallel = false);

}  // namespace cvtmesh
