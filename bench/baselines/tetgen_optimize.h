// TetGen's own mesh optimization (-O: flips and smoothing, no point insertion) on an existing
// mesh, boundary kept: a baseline of `cvtmesh compare`.
#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct TetgenOptimizeOptions {
  int level = 9;  // -O level (0..9): iterations of the optimization
  int flags = 3;  // 1 flips, 2 smoothing, 4 point insertion/deletion (not used: keep vertices)
};

// Reconstructs `mesh` in TetGen (-r), refines it to radius-edge ratio 1.414 (-q: TetGen 1.5 runs
// its optimizer only together with refinement) and optimizes it (-O level/flags), keeping the
// boundary mesh (-Y). Replaces the tets and interior positions; appends the inserted points.
void tetgen_optimize(TetMesh& mesh, const TetgenOptimizeOptions& options = {});

}  // namespace cvtmesh
