// Point location in a planar triangle mesh by a (randomised) visibility walk.
#pragma once
#include <vector>

#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

struct Locate2dResult {
  int tri = -1;        // a triangle whose closure contains p; -1 if the walk was stopped
  int on_edge = -1;    // local edge (0..2, opposite that vertex) of tri on which p lies, or -1
  int on_vertex = -1;  // vertex id of tri that p coincides with, or -1
};

// Walks from triangle `start` towards the point p (2 doubles) with exact orient2d tests, never
// crossing a packed slot s = 3t+e with stop[s] != 0 (pass an empty vector to allow every edge)
// nor leaving the mesh (adj = -1). Returns tri = -1 if the walk would have to cross such an edge
// or exceeds `max_steps` (0: 4 * #T + 16). mesh.adj must be built.
Locate2dResult locate2d(const TriMesh2& mesh, const double* p, int start,
                        const std::vector<char>& stop = {}, long max_steps = 0);

}  // namespace cvtmesh
