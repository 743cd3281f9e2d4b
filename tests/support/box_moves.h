#pragma once
// The vertex moves of a mesh of the box [0, n]^3 (tests/support/test_meshes.h jittered_box)
// against its start: what every boundary operator on the box must keep.
#include <array>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh::testing {

// How many vertices moved, by the number of box planes their start position lies on (0 interior,
// 1 face, 2 edge, 3 corner). Adds a test failure for every corner that moved, every coordinate
// that put a vertex on a plane and did not stay there (1e-12), and every vertex outside the box.
// The vertices compared are those of both meshes.
std::array<int, 4> box_moves(const TetMesh& m, const TetMesh& start, int n);

}  // namespace cvtmesh::testing
