// A partition of a tet mesh into parts of equal size (METIS's k-way partition of the tets' dual
// graph: tets joined by their common faces), for optimizing each part alone with its interface
// pinned (optimize_partitioned.h). Deterministic: the same mesh and arguments give the same parts.
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct TetPartition {
  std::vector<int> part;   // #T: the part of each tet, in [0, parts)
  int nb_cut_faces = 0;    // faces between tets of different parts
  int nb_avoided_cut = 0;  // of those, faces with a vertex `avoid` marked (0 when METIS could)
};

// `avoid` (#V or empty): vertices the interfaces should not pass through (the previous round's
// interface). In two parts, the tets joined across a face with such a vertex are kept together
// (each group one vertex of METIS's graph, weighing its tets) while no group outweighs half a
// part, so the new interface runs elsewhere. Otherwise the faces touching them weigh
// `avoid_weight` times more in the cut METIS minimises, and nb_avoided_cut says how many were cut
// all the same: on c1m (930k tets) in 4 parts the groups gave METIS a cut of 255,781 faces (round
// 1: 11,099), the weights one of 17,178 with 276 on the old interface. mesh.adj must be built;
// deleted tets (tets[4t] < 0) get part -1. Throws InvariantError if METIS fails, InputError if
// parts < 1 or more than the tets.
TetPartition partition_tets(const TetMesh& mesh, int parts, const std::vector<char>& avoid = {},
                            int avoid_weight = 1000);

}  // namespace cvtmesh
