// Bridge between the current Gmsh model (SDK, in this process) and MeshData. Every Gmsh call of
// the project goes through core/io/. Requires a live GmshSession.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// Reads the mesh of the current Gmsh model: dim = 3 (tets), 2 (planar triangles) or -1 (the
// highest dimension that has elements); triangles on surfaces in space that bound no volume, with
// dim -1 or 3, are read as a surface mesh in space (a TetMesh without tets). Keeps entities,
// boundaries, physical groups, node and element tags, node classification, lower-dimensional
// elements. Throws InputError on an empty mesh, unsupported element types (hex, prism, pyramid,
// quads, second order...), non-planar 2D meshes, inverted or flat elements, or an inconsistent mesh
// (check_mesh).
MeshData mesh_from_gmsh(int dim = -1, const std::string& what = "model");

// Fills in missing model information (entities for region/surface/curve tags, vertex
// classification) so that a mesh that did not come from Gmsh can be written as a Gmsh model.
void complete_model_info(MeshData& data);

// Element tags that mesh_to_gmsh gave to the live simplices (tets in 3D, triangles in 2D and in
// a surface mesh in space), in element order — the keys of $ElementData.
struct GmshWritten {
  std::vector<std::size_t> element_tags;  // per live simplex of the mesh dimension, in order
  std::vector<std::size_t> node_tags;     // per vertex
};

// Creates (and makes current) a new Gmsh model `model_name` holding data: entities, nodes with
// their classification and tags, elements, physical groups.
GmshWritten mesh_to_gmsh(const MeshData& data, const std::string& model_name);

// Replaces the mesh of the current Gmsh model in place (in-process scripting): nodes and
// elements of the optimized dimension are replaced, entities and physical groups stay.
GmshWritten replace_gmsh_mesh(const MeshData& data);

// Adds one ElementData view per field on the given elements of the current model; returns tags.
std::vector<int> add_element_views(const std::vector<ElementField>& fields,
                                   const std::vector<std::size_t>& element_tags);

}  // namespace cvtmesh
