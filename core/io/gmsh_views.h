// The post-processing views of a file Gmsh opened ($NodeData / $ElementData of a .msh) read into
// DataViews of the mesh, and DataViews added to the model being written.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "core/mesh/data_views.h"
#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// The model-based views `views` (tags) of the current Gmsh session as views of `data` (just read:
// node tags -> vertices, element tags -> simplices of the mesh dimension), with
// mesh_fingerprint(data). NodeData and ElementData are kept, every step and component; values on
// other nodes or elements (order-2 mid-edge nodes, boundary elements) are left out. A view that
// cannot be kept (list-based, ElementNodeData, GaussPointData, none of its values on the mesh)
// gets one line in `notes` naming `what` and the view. Requires a live GmshSession.
std::vector<DataView> read_gmsh_views(const std::vector<int>& views, const MeshData& data,
                                      const std::string& what, std::vector<std::string>& notes);

// Adds the views to the current Gmsh model: NodeData on node_tags[vertex], ElementData on
// cell_tags[live simplex] (0: not written). With nb_elements > 0 (the elements tagged 1..N in
// file order), ElementData covers every element, NaN on those without a value, as meshio reads
// it (by position). Returns the new view tags.
std::vector<int> add_data_views(const std::vector<DataView>& views,
                                const std::vector<std::size_t>& node_tags,
                                const std::vector<std::size_t>& cell_tags,
                                std::size_t nb_elements = 0);

}  // namespace cvtmesh
