// Carrying an input's post-processing views onto another mesh of the same domain (the optimized
// one): the solution a user stored with the mesh is not lost when the mesh changes.
#pragma once
#include <vector>

#include "core/mesh/data_views.h"
#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// The views of from.model().views that belong to `from` (their fingerprint is from's), carried
// onto `to` (same dimension): a node value is interpolated linearly in the simplex of `from` that
// holds the vertex; an element value is the one of the simplex of `from` that holds the
// simplex's centroid. A point outside `from` (a boundary vertex moved on a curved surface) takes
// the nearest simplex found, its barycentric coordinates clamped to the simplex. NaN where a
// value used is NaN. Each result carries mesh_fingerprint(to). Views of another mesh are left out.
std::vector<DataView> transfer_views(const MeshData& from, const MeshData& to);

}  // namespace cvtmesh
