// A mesh file that holds a 3D model's surface mesh and no tetrahedra (`gmsh -2 -save_all`, a
// surface-only export, a .msh 2.2 / .vtk / .unv / .bdf of closed surfaces): its volumes are
// meshed by Gmsh, the surface mesh kept as it is, so that it can be optimized like any 3D mesh.
#pragma once
#include <string>
#include <vector>

#include "core/io/read_mesh.h"

namespace cvtmesh {

// True if the current Gmsh model (a mesh file just opened) holds triangles and no element of
// dimension 3 and either has volume entities or triangles that are not all in one plane z = const
// and close up (every edge on an even number of triangles): a surface mesh whose inside is wanted.
bool is_surface_mesh_of_volumes();

// Meshes the volumes of the current Gmsh model (is_surface_mesh_of_volumes()): the points,
// curves and surfaces with their nodes, elements and physical groups are copied into a new model
// in which each volume is bounded by the same surfaces (the file's volumes; without any, one per
// closed shell of the triangles, a shell inside an odd number of others being a cavity of the
// innermost one around it), meshed by generate(3) with the meshing options of `options`
// (optimizer, size factor, seed). The new model becomes current; the opened one is removed.
// Returns the tags of the volumes meshed. Throws InputError("<what>: ...") if the surfaces carry
// other elements than linear triangles or Gmsh cannot mesh them (a self-intersecting surface...).
// Requires a live GmshSession.
std::vector<int> mesh_volumes_of_surface_mesh(const std::string& what, const ReadOptions& options);

}  // namespace cvtmesh
