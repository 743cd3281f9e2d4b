// The Voronoi cell of a mesh vertex restricted to its region of the domain: the union over the
// tets it reaches of (tet ∩ bisector half-spaces of the vertex's Delaunay neighbours), found by
// a breadth-first search from the vertex's star that never crosses the domain boundary or a
// constrained face (region interface). Its moments give the mass centroid and the CVT energy.
#pragma once
#include <vector>

#include "core/cvt/cell_mesh.h"
#include "core/cvt/polytope_clip.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct PlaneRef {
  Vec3 n;      // unit normal
  double h;    // distance of the plane from the cell's generator
  double tol;  // the clip's tolerance for this plane: CellMesh::eps * |n|
};

struct CellWorkspace {
  Polytope poly, scratch;
  std::vector<PlaneRef> planes;  // bisector planes of the generators, nearest first
  std::vector<int> queue, generators, hit, reached;
  std::vector<int> mark;  // #T, stamp of the last vertex that visited the tet
  int stamp = 0;
  std::vector<int> vmark;  // #V, stamp of the last list a vertex was added to (generators)
  int vstamp = 0;
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
// The generators whose bisectors clip the cell are the vertices of v's star and of the tets
// next to it; where the cell reaches tets with other vertices (a constrained mesh is not Delaunay
// near its boundary), it is recomputed with those too, so that cells do not overlap.
CellIntegrals restricted_voronoi_cell(const TetMesh& mesh, const CellMesh& cells, int v,
                                      CellWorkspace& ws, const std::vector<double>* rho = nullptr);

// The same integrals from the Delaunay dual, without clipping: the cell of an interior vertex of a
// (locally) Delaunay mesh is the convex hull of the circumcentres of its tets, decomposed into the
// signed tets (v, mid(vw), cc(face), cc(tet)). Applies when every tet of v's star is
// CellMesh::dual_ok; returns false otherwise (`out` then partial: use restricted_voronoi_cell). For
// a vertex on the boundary the pieces of its boundary faces lie in those faces' planes: the result
// is its cell restricted by the boundary triangles' planes — the restricted cell where the boundary
// is flat (tested to 1e-9 against clipping), within ~1e-4 of its volume on a curved polyhedral
// surface, where only the energy of a fixed vertex's cell is used. The energy of each piece takes
// rho at the piece's centroid: it differs from the clipped cell's by O(h |grad rho| / rho). The
// density is the one CellMesh was prepared with.
bool dual_voronoi_cell(const TetMesh& mesh, const CellMesh& cells, int v, CellIntegrals& out);

// The dual pieces of tet t with circumcentre cc (see CellMesh::dual_piece): for each local vertex
// k, out[6k..6k+5] = volume, mass, moment (3), energy relative to vertex k, under the density
// rho[vertex] + grad.(x - vertex) (uniform 1 if rho is null).
void dual_tet_pieces(const TetMesh& mesh, int t, const Vec3& cc, const std::vector<double>* rho,
                     const double* grad, double* out);

// 4*#T flags into `flags` (its array reused): face f of tet t is a constrained triangle (boundary
// or interface).
void constrained_face_flags(const TetMesh& mesh, std::vector<char>& flags);

}  // namespace cvtmesh
