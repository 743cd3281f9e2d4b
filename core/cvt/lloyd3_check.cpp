#include "core/cvt/lloyd3_check.h"

#include <string>
#include <vector>

#include "core/mesh/check_mesh.h"
#include "core/util/error.h"

namespace cvtmesh {

void verify_lloyd3_mesh(const TetMesh& m, bool full) {
  if (full) {
    const MeshCheck c = check_mesh(m);
    if (!c.ok)
      throw InvariantError("Lloyd iteration produced an invalid mesh: " +
                           (c.problems.empty() ? std::string("?") : c.problems.front()));
  } else {
    if (const int bad = last_non_positive_tet(m); bad >= 0)
      throw InvariantError("Lloyd iteration produced an invalid mesh: tet " + std::to_string(bad) +
                           " is inverted or flat");
  }
  // Every vertex that had tets must still have some (no point lost in a hole).
  std::vector<char> used(m.nb_vertices(), 0);
  for (int t = 0; t < m.nb_tets(); ++t)
    if (m.tets[4 * t] >= 0)
      for (int k = 0; k < 4; ++k) used[m.tets[4 * t + k]] = 1;
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim == 3 && !used[v])
      throw InvariantError("Lloyd iteration left interior vertex " + std::to_string(v) +
                           " outside every tet");
}

}  // namespace cvtmesh
