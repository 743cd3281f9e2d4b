// An independent check of our quality figures: Gmsh's own ICN (inverse condition number) of every
// element, computed by Gmsh's Plugin(AnalyseMeshQuality).
#pragma once
#include <vector>

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// Loads `data` as a temporary Gmsh model (mesh_to_gmsh), runs Plugin(AnalyseMeshQuality) with
// ICNMeasure = 1, CreateView = 1, DimensionOfElements = data.dim, reads its "ICN 3D" / "ICN 2D"
// view and returns the values in our element order (one per live tet / triangle). The model and
// the views it made are removed; a caller's current model stays current. Comparable with
// tet_quality / tri_quality(..., Measure::kGmshIcn). Throws InputError if Gmsh fails or reports
// no value for an element.
std::vector<double> gmsh_icn_per_element(const MeshData& data);

}  // namespace cvtmesh
