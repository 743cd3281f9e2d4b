// Interior vertex insertion (Stellar / CGAL-style): the tets of a cavity are replaced by the tets
// joining a new point p to every boundary face of the cavity. Valid when the cavity is
// star-shaped from p (every new tet positively oriented, exact orient3d) and holds no vertex
// inside (every vertex of its tets is on its boundary). The cavity never crosses a constrained
// face, so p lies strictly inside one region and the constrained triangles stay as they are.
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/swap/constrained_faces.h"
#include "core/swap/swap_plan.h"

namespace cvtmesh {

// The smallest cavity around the live tet t: t and the tets behind its faces that are not
// constrained (and of t's region), t first. Needs mesh.adj.
std::vector<int> tet_cavity(const TetMesh& mesh, const ConstrainedFaces& constrained, int t);

// Bowyer-Watson growth of a cavity around p: adds, until none is left or the cavity has
// max_size tets, the tets behind its unconstrained boundary faces (same region) whose
// circumsphere strictly contains p (exact insphere), in a fixed order. Needs mesh.adj.
void grow_cavity(const TetMesh& mesh, const ConstrainedFaces& constrained, const double* p,
                 std::vector<int>& cavity, int max_size);

// A point of the cavity's kernel (from which it is star-shaped) as far as possible from the
// planes of its boundary faces: a max-min ascent on the signed distances to those planes from
// the centroid of the cavity's vertices (exact steps between the planes, at most 100). Returns
// the smallest distance reached (<= 0: no kernel found, p is then the best point seen); p gets 3
// doubles. A floating-point estimate: plan_insert_vertex decides with orient3d. Needs mesh.adj.
double cavity_kernel_center(const TetMesh& mesh, const std::vector<int>& cavity, double* p);

// Plans the insertion of p (3 doubles) as the new vertex mesh.nb_vertices() into `cavity` (live
// tet ids of one region, connected); changes nothing. plan.new_tets join the new vertex to the
// cavity's boundary faces. status kMixedRegions, kInteriorVertex, kNotConvex (a new tet is not
// positively oriented: the cavity is not star-shaped from p). Needs mesh.adj.
SwapPlan plan_insert_vertex(const TetMesh& mesh, const std::vector<int>& cavity, const double* p);

// Commits a valid plan from plan_insert_vertex (made on this mesh as it is): appends p as an
// interior vertex (vclass {3, plan.region}, node tag 0 when node tags are kept) and replaces the
// cavity (apply_swap). Returns the new vertex id. Throws std::invalid_argument if the plan is
// not valid.
int insert_vertex(TetMesh& mesh, SwapPlan& plan, const double* p,
                  std::vector<int>* free_slots = nullptr);

}  // namespace cvtmesh
