// The Voronoi cell of a mesh vertex restricted to its region of the domain: the union over the
// tets it reaches of (tet ∩ bisector half-spaces of the vertex's Delaunay neighbours), found by
// a breadth-first search from the vertex's star that never crosses the domain boundary or a
// constrained face (region interface). Its moments give the mass centroid and the CVT energy.
#pragma once
#include <vector>

#include "core/cvt/polytope_clip.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/vertex_star.h"

namespace cvtmesh {

struct CellWorkspace {
  Polytope poly, scratch;
  std::vector<Vec3> normals;
  std::vector<double> offsets;
  std::vector<int> queue;
  std::vector<int> mark;  // #T, stamp of the last vertex that visited the tet
  int stamp = 0;
};

// Integrals over the restricted cell of v under a density rho that is linear in each tet of the
// mesh (P1, from per-vertex values; null = uniform density 1), relative to z = the position of v:
// volume, mass = int rho, first moment int rho (x - z), energy int rho |x - z|^2 (rho taken at
// the centroid of each piece for the energy; mass and moment are exact).
struct CellIntegrals {
  double volume = 0;
  double mass = 0;
  Vec3 moment{0, 0, 0};
  double energy = 0;
  // Mass centroid, z + moment / mass (z itself for an empty cell).
  Vec3 centroid(const double* z) const;
};
// `constrained`: 4*#T flags of faces not to cross. `eps`: length tolerance of the clipping.
CellIntegrals restricted_voronoi_cell(const TetMesh& mesh, const VertexStar& star,
                                      const std::vector<char>& constrained, int v, double eps,
                                      CellWorkspace& ws, const std::vector<double>* rho = nullptr);

// The same integrals from the Delaunay dual, without clipping: the cell of an interior vertex of a
// (locally) Delaunay mesh is the convex hull of the circumcentres of its tets, decomposed into the
// signed tets (v, mid(vw), cc(face), cc(tet)). Applies only when v is interior and every
// circumcentre of its tets lies in the region (found by a short walk that crosses no constrained
// face); returns false otherwise (use restricted_voronoi_cell). `cc`: 3*#T tet circumcentres.
bool dual_voronoi_cell(const TetMesh& mesh, const VertexStar& star,
                       const std::vector<char>& constrained, const std::vector<double>& cc, int v,
                       const std::vector<double>* rho, CellIntegrals& out);

// 3*#T circumcentres of the live tets.
std::vector<double> tet_circumcenters(const TetMesh& mesh);

// 4*#T flags: face f of tet t is a constrained triangle (boundary or interface).
std::vector<char> constrained_face_flags(const TetMesh& mesh);

}  // namespace cvtmesh
