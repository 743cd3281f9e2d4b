// Volumes that overlap or touch without sharing their mesh: an assembly meshed part by part
// (Gmsh's demos step_assembly — STEP parts in contact, not fragmented — and neuron — dendrites
// through a sphere without a boolean). Their boundaries intersect each other, so the whole cannot
// be tetrahedralized again, but each volume alone can: optimize() then runs on each volume apart
// (its vertices shared with the others pinned, extract_regions), and `cvtmesh check` reports the
// overlap as a warning, not as a defect of the mesh.
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// The volume tags of `mesh` if it has two or more volumes, its structural defects
// (find_structural_defects: intersecting boundary triangles, coincident vertices) are not empty,
// and each volume alone has none: the defects lie only between volumes. Empty otherwise (one
// volume, no defect, or a volume defective in itself).
std::vector<int> volumes_defective_only_together(const TetMesh& mesh,
                                                 double relative_tolerance = 1e-8);

}  // namespace cvtmesh
