// The reference of a sizing given as a file (OptimizeOptions::sizing = a path): the mesh whose
// local edge length becomes the background sizing H of the CVT density. A mesh file is read as it
// is; a model Gmsh meshes (.geo, .step, ...) is meshed first, so H is the model's own mesh sizes
// (its points' sizes, size fields, Mesh.MeshSizeFactor ...).
#pragma once
#include <memory>
#include <string>

#include "core/io/read_mesh.h"
#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// Reads `path` as a mesh of dimension dim (2 or 3; -1: the file's highest). Throws InputError
// naming the file for a missing or unreadable file, and for one without triangles (dim 2) or
// tetrahedra (dim 3). `options` are those of the input (a .geo's --set values apply to both).
std::shared_ptr<const MeshData> read_sizing_reference(const std::string& path, int dim,
                                                      ReadOptions options = {});

}  // namespace cvtmesh
