// The boundary invariants of a free-boundary run (checked at its end, with verify_optimized's
// VerifyOptions{boundary_moves = true} for the rest): fixed boundary vertices (corners, locked,
// unclassifiable) unmoved; every moved boundary vertex on its own entity of the reference geometry
// (distance <= on_entity * diagonal); the two-sided Hausdorff distance between the new and the
// reference boundary <= hausdorff; every region's volume within `volume` (relative). A violation
// throws InvariantError; the measured values are returned for the report.
#pragma once
#include <vector>

#include "core/geometry/boundary_geometry.h"
#include "core/boundary/boundary_hausdorff.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct FreeBoundaryTolerances {
  double on_entity = 1e-9;  // relative to the bounding-box diagonal
  double hausdorff = 0;     // absolute; 0: not checked (reported only)
  double volume = 5e-3;     // relative change of each region's volume
};

struct FreeBoundaryReport {
  int nb_moved = 0;           // boundary vertices that moved
  double max_off_entity = 0;  // absolute distance of a moved vertex to its entity
  HausdorffDistance hausdorff;
  double diagonal = 0;
  double max_volume_change = 0;                      // relative, over the regions
  double tri_q_min_before = 0, tri_q_min_after = 0;  // worst boundary triangle Q
};

FreeBoundaryReport verify_free_boundary(const TetMesh& before, const TetMesh& after,
                                        const BoundaryModel& model,
                                        const FreeBoundaryTolerances& tolerances);

// The minimum Q (Measure::kQ) over a mesh's boundary triangles (1 if there are none).
double boundary_triangle_q_min(const TetMesh& mesh);

}  // namespace cvtmesh
