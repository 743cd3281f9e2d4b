// TriMesh2: a planar triangle mesh as flat, 0-based arrays.
#pragma once
#include <cstddef>
#include <vector>

#include "core/mesh/model_info.h"
#include "core/mesh/vertex_class.h"

namespace cvtmesh {

struct TriMesh2 {
  // #V by 2 coordinates (x, y), row-major. The mesh lies in the plane z = z0.
  std::vector<double> xy;
  double z0 = 0.0;
  // #V classification (dim 2 = interior vertex, free to move; 1 on a curve; 0 corner).
  std::vector<VertexClass> vclass;
  // #V original Gmsh node tags (0 for a new vertex); may be empty.
  std::vector<std::size_t> node_tags;

  // #T by 3 vertex ids, counter-clockwise (positive signed area).
  std::vector<int> tris;
  // #T surface (Gmsh entity) tag.
  std::vector<int> tri_region;
  // #T original Gmsh element tags; may be empty.
  std::vector<std::size_t> tri_tags;
  // Surface tags whose triangles were clockwise in the input (normal along -z): stored
  // counter-clockwise here, written back clockwise.
  std::vector<int> cw_surfaces;

  // #E by 2 boundary and interface edges (constrained segments).
  std::vector<int> edges;
  // #E Gmsh curve tag of each edge.
  std::vector<int> edge_curve;
  // #E original Gmsh element tags; may be empty.
  std::vector<std::size_t> edge_tags;

  // 3*#T packed adjacency: adj[3t+e] = 3t'+e' where edge e of t (opposite vertex e) is edge e'
  // of t', or -1 on the boundary. Built by build_adjacency2().
  std::vector<int> adj;

  ModelInfo model;

  int nb_vertices() const { return static_cast<int>(xy.size() / 2); }
  int nb_tris() const { return static_cast<int>(tris.size() / 3); }
  int nb_edges() const { return static_cast<int>(edges.size() / 2); }
  const double* point(int v) const { return &xy[2 * static_cast<std::size_t>(v)]; }
  double* point(int v) { return &xy[2 * static_cast<std::size_t>(v)]; }
};

// Fills mesh.adj from mesh.tris (dead triangles, tris[3t] < 0, get -1). Throws InputError on a
// non-manifold edge (shared by more than two triangles).
void build_adjacency2(TriMesh2& mesh);

}  // namespace cvtmesh
