// Point location in a tet mesh by a visibility walk with exact orientation tests.
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

enum class LocateStatus {
  kInside,   // the point is in (or on the boundary of) the returned tet
  kBlocked,  // the walk had to leave the domain or cross a blocked face; tet = last tet visited
};

struct LocateResult {
  LocateStatus status = LocateStatus::kBlocked;
  int tet = -1;
};

// Walks from start_tet towards x. `blocked` (optional, 4*#T flags) marks faces the walk may not
// cross (region interfaces); the domain boundary (adj < 0) always blocks. At most max_steps.
LocateResult locate_point(const TetMesh& mesh, const double* x, int start_tet,
                          const std::vector<char>* blocked = nullptr, int max_steps = 100000);

// Barycentric coordinates of x in tet t (they sum to 1; negative outside).
void barycentric(const TetMesh& mesh, int t, const double* x, double w[4]);

}  // namespace cvtmesh
