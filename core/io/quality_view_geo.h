// How a quality view is shown when Gmsh reads .geo text: the first field's view coloured over the
// range of its finite values, the other fields' views hidden, and a 3D mesh cut through its
// bounding box's centre by the plane facing the camera (camera_cut.h). The companion .opt of
// `optimize --quality` (write_mesh.cpp) and the ONELAB client's load script (plugin/onelab_main)
// both emit it.
#pragma once
#include <string>
#include <vector>

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// The range [lo, hi] of the finite values of a field (hi > lo: a constant field gets 1e-6).
void finite_range(const ElementField& field, double& lo, double& hi);

// The statements, one per line, for the views of `fields` whose first index is the .geo
// expression `first_view` (e.g. "0" or "cvt_q"): RangeType custom over finite_range, the others
// hidden, the camera-facing cut for a 3D mesh. Empty for no fields.
std::string quality_view_geo(const MeshData& data, const std::vector<ElementField>& fields,
                             const std::string& first_view);

}  // namespace cvtmesh
