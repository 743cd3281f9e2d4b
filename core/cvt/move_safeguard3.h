// The safeguard of every move of the 3D Lloyd iteration: a free vertex's move towards its goal is
// halved until the point lies in the vertex's region, reached from its star without crossing the
// boundary or an interface (so the mesh can follow it by flips or a rebuild).
#pragma once
#include <functional>
#include <vector>

#include "core/cvt/cell_mesh.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// The move of v (a vertex with tets in cm's star) towards `goal` (3 values), shortened up to
// max_halvings times. Writes the position to `out` (v's own if every try failed); returns false
// if the move was shortened.
bool safe_target3(const TetMesh& mesh, const CellMesh& cm, int v, const double* goal,
                  int max_halvings, double* out);

// safe_target3 for every vertex of free_ids (goal/out: 3 per free vertex), in parallel; returns
// how many moves were shortened.
int safe_targets3(const TetMesh& mesh, const CellMesh& cm, const std::vector<int>& free_ids,
                  const std::vector<double>& goal, int max_halvings, std::vector<double>& out);

// The safeguard as the moves see it: goal -> out (3 per free vertex of the current evaluation),
// returns how many moves were shortened.
using MoveSafeguard3 =
    std::function<int(const std::vector<double>& goal, std::vector<double>& out)>;

}  // namespace cvtmesh
