// The volume budget of a free-boundary run: each region's volume may change by at most
// `tolerance` (relative) over the whole run. Interior moves and flips conserve volumes exactly;
// a boundary vertex move changes the volume of the regions of its star by the signed volume its
// fan sweeps. A move is admitted only if every region's running change stays within the budget,
// so the end-of-run volume bound holds by construction.
#pragma once
#include <limits>
#include <utility>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {

// Each region's volume (sorted by region tag): a compensated sum of the live tets' volumes.
std::vector<std::pair<int, double>> region_volumes_of(const TetMesh& mesh);

struct VolumeBudget {
  std::vector<int> region;                                     // region tags
  std::vector<double> volume;                                  // their volumes at the start
  std::vector<double> change;                                  // running signed change
  double tolerance = std::numeric_limits<double>::infinity();  // relative

  // Per region of the mesh (region_volumes).
  static VolumeBudget of(const TetMesh& mesh, double tolerance);
  // The signed volume change of each region (#region) if v moves to q; false if it would take a
  // region out of the budget.
  bool admits(const TetMesh& mesh, const VertexTets& star, int v, const double* q,
              std::vector<double>& delta) const;
  void commit(const std::vector<double>& delta);
};

}  // namespace cvtmesh
