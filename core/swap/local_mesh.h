// A local copy of a few tets of a mesh, to try a composite operation (flips, vertex insertion,
// smoothing) on it and commit the result back only if it is better (or drop it: nothing to undo).
// The copy is a TetMesh of its own: every operation of the library applies to it unchanged.
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/swap/constrained_faces.h"

namespace cvtmesh {

struct LocalMesh {
  // The copy: the tets, their vertices (renumbered 0..), adjacency built. Its constrained
  // triangles (tris) are the boundary faces of the tets' union and the mesh's constrained faces
  // between two of the tets, so that operations on the copy keep its boundary. A vertex is free
  // (vclass.dim 3) only if it is free in the mesh and all the tets around it are in the copy:
  // moving it changes no tet outside.
  TetMesh mesh;
  std::vector<int> global_vertex;  // local vertex -> vertex of the mesh (#V of the copy)
  std::vector<int> global_tet;     // local tet -> tet of the mesh (#T of the copy)
  int region = 0;                  // region tag of all the tets
};

// Copies the live tets `tets` (distinct ids, all of one region) of mesh (adjacency built).
// Throws std::invalid_argument if a tet is dead or the regions differ.
LocalMesh extract_local_mesh(const TetMesh& mesh, const ConstrainedFaces& constrained,
                             const std::vector<int>& tets);

// Writes `after` (the copy, changed by operations that kept its constrained triangles, moved
// only its free vertices and may have appended free vertices) back into mesh: the moved vertices'
// coordinates, the new vertices (appended, vclass {3, region}, node tag 0), and the tets of
// `after` that are not tets of `local` replace those of `local` not in `after` (apply_swap: the
// adjacency is repaired locally; dead slots reused from *free_slots first, left dead and pushed
// there). Checks first, changing nothing if a check fails: every tet of `after` positively
// oriented (exact orient3d), the non-free vertices unmoved, every triangle of `local.mesh.tris`
// (the copy's hull and the constrained faces inside it) still a face of a tet of `after`. Returns
// false then, true once committed. InvariantError (from apply_swap) if the changed tets do not fill
// the same cavity.
bool commit_local_mesh(TetMesh& mesh, const LocalMesh& local, const TetMesh& after,
                       std::vector<int>* free_slots = nullptr);

}  // namespace cvtmesh
