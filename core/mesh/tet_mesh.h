// TetMesh: a tetrahedral mesh as flat, 0-based arrays (geogram / MMG style).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "core/mesh/model_info.h"
#include "core/mesh/vertex_class.h"

namespace cvtmesh {

struct TetMesh {
  // #V by 3 coordinates, row-major.
  std::vector<double> xyz;
  // #V classification (dim 3 = interior vertex, free to move).
  std::vector<VertexClass> vclass;
  // #V original Gmsh node tags (0 for a vertex created by us); may be empty.
  std::vector<std::size_t> node_tags;

  // #T by 4 vertex ids; positively oriented: orient3d(a,b,c,d) > 0 means d is on the positive side
  // of (a,b,c) in our convention, i.e. signed volume (b-a).((c-a)x(d-a)) / 6 > 0.
  std::vector<int> tets;
  // #T region (Gmsh volume entity) tag.
  std::vector<int> tet_region;
  // #T original Gmsh element tags (0 for new); may be empty.
  std::vector<std::size_t> tet_tags;

  // #F by 3 boundary and interface triangles (the constrained faces), any orientation.
  std::vector<int> tris;
  // #F Gmsh surface entity tag of each triangle.
  std::vector<int> tri_surface;
  // #F original Gmsh element tags; may be empty.
  std::vector<std::size_t> tri_tags;

  // 4*#T packed adjacency: adj[4t+f] = 4t'+f' where face f of t (opposite vertex f) is face f' of
  // t', or -1 on the domain boundary. Built by build_adjacency().
  std::vector<int> adj;

  ModelInfo model;

  int nb_vertices() const { return static_cast<int>(xyz.size() / 3); }
  int nb_tets() const { return static_cast<int>(tets.size() / 4); }
  int nb_tris() const { return static_cast<int>(tris.size() / 3); }
  const double* point(int v) const { return &xyz[3 * static_cast<std::size_t>(v)]; }
  double* point(int v) { return &xyz[3 * static_cast<std::size_t>(v)]; }
};

// Face f of a tet (opposite its vertex f), ordered so that it is oriented outwards
// (its normal by the right-hand rule points away from vertex f).
extern const int kTetFace[4][3];
// The 6 edges of a tet as local vertex pairs.
extern const int kTetEdge[6][2];

}  // namespace cvtmesh
