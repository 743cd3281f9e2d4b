// Local improvement of a planar triangle mesh that can never make it worse: rounds of edge
// flips accepted by flip2d_no_worse (never across a constrained edge, never between two
// surfaces) and of vertex moves guarded on their star, until neither changes anything.
//
// Vertex move. Free vertex: vclass.dim 2 (not pinned: pin_vertices.h), on no constrained edge
// (mesh.edges) and no open edge (a closed star), not marked in `fixed`.
// propose: the mean of its edge neighbours (Laplacian), the area-weighted mean of its triangles'
// centroids, each also a half and a quarter of the way; then a compass search from the best
// (8 directions from a tenth of the star's shortest edge, halved 6 times, at most 4 steps of
// each length).
// check: every triangle of the star positive (exact orient2d).
// accept: over the star, the minimum Q and the minimum angle do not fall, the maximum angle
// does not rise, and the sum of Q rises (by more than 1e-12 relative).
// apply: the coordinates; connectivity never changes.
// So the mesh's minimum and average Q, minimum and maximum angle are never worse, and the
// average Q rises with every accepted operation. Serial, in vertex order: deterministic. After
// the first sweep, only the vertices whose star changed (a neighbour moved, a flip) are tried.
#pragma once
#include <vector>

#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

struct ImproveLocal2dOptions {
  int max_rounds = 20;  // flip pass + move sweep; stops earlier when neither changes anything
};

struct ImproveLocal2dStats {
  long nb_flips = 0;
  long nb_moves = 0;
  int rounds = 0;
  int nb_free = 0;  // vertices free to move
};

// mesh: a valid planar mesh (check_mesh) with its adjacency built; kept valid. fixed: #V flags
// of vertices that must not move besides the constrained ones (empty: none).
ImproveLocal2dStats improve_local2d(TriMesh2& mesh, const std::vector<char>& fixed = {},
                                    const ImproveLocal2dOptions& options = {});

}  // namespace cvtmesh
