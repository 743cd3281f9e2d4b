// The elements a .msh file gets, as Gmsh would save the model (Mesh.SaveAll = 0), so that the
// files read back the same in Gmsh, meshio and other tools:
//  - meshed by Gmsh from a .geo / CAD model with physical groups: the elements of the entities in
//    a physical group of their dimension (Gmsh's own `gmsh -3 model.geo` output);
//  - read from a .msh (or another mesh file Gmsh opens): the element blocks that file held, no
//    others (not the boundary facets the reader restored for the optimizer);
//  - otherwise, or with save_all: every element (Mesh.SaveAll = 1).
// The optimizer works on every element; this only selects what is written.
#pragma once
#include <vector>

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

struct MshSelection {
  MeshData data;  // a copy holding only the selected elements (and every vertex, entity, group)
  // Mesh.SaveAll to give Gmsh: 0 when every selected element is in a physical group (MSH 2.2 then
  // writes the groups as the elements' physical tags), 1 otherwise.
  bool save_all = true;
  bool outside_groups =
      false;  // some selected elements are in no physical group (and groups exist)
  // Per simplex of data.dim in the copy: its index among the live simplices of the original (the
  // index of its value in a quality field), or -1 (dead, or not selected: marked dead here).
  std::vector<long> field_index;
};

MshSelection select_msh_elements(const MeshData& data, bool save_all);

// Element tags 1..N in the order Gmsh writes the elements (by dimension, entity tag, element
// type): per-element data is then read back by position (meshio) and by tag (Gmsh) alike. Tags
// that are 1..N in that order already are kept. Dead elements and the hidden interfaces of kept
// cells (hybrid meshes) get no tag. Returns N.
std::size_t number_in_file_order(MeshData& data);

// Node tags 1..N in the order Gmsh writes the vertices (by entity dimension and tag, then vertex
// order), for per-node data read back by position (meshio) as by tag (Gmsh). Kept when already
// so, and for order-2 meshes and meshes with periodic links (whose node tags are kept: Gmsh reads
// the data by tag). Returns true if the tags are in file order afterwards.
bool number_nodes_in_file_order(MeshData& data);

// The fields (one value per live simplex of data.dim, element order) spread over every written
// element, by tag 1..N after number_in_file_order: NaN for the elements that are not simplices
// of the mesh dimension (points, lines, boundary facets, kept cells).
std::vector<ElementField> fields_on_all_elements(const MshSelection& numbered,
                                                 const std::vector<ElementField>& fields,
                                                 std::size_t nb_elements);

}  // namespace cvtmesh
