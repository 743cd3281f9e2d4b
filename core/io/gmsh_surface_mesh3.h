// A mesh of triangles on surfaces in space that bound no volume (an open shell, CAD faces, a
// BEM or shell-FE mesh, a plate in the plane x = 0): read as a surface mesh in 3D, a TetMesh
// without tets whose `tris` are the surface (core/mesh/tet_mesh.h), optimized on its surfaces
// (core/boundary/optimize_surface_mesh.h) instead of being refused as a non-planar 2D mesh.
#pragma once
#include <string>

#include "core/io/surface_io.h"
#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// True if the current Gmsh model's highest elements are 2D and their corner nodes are not all in
// one plane z = const (z_range.h): not a 2D mesh, a surface mesh in space. Requires a live
// GmshSession.
bool gmsh_surface_mesh_in_space();

// An open surface of a surface file (.stl, .off, .obj, .ply) that is not in a plane z = const, as
// a surface mesh in space: one discrete Gmsh surface (tag 1) holding its triangles, read back by
// mesh_from_gmsh (vertices on surface 1; its borders and sharp edges become the discrete
// geometry's curves when it is optimized). `name`: the model's name. Throws InputError("<what>:
// ..."). Starts its own GmshSession if none is live.
MeshData surface_mesh_in_space(const SurfaceMesh& surface, const std::string& name,
                               const std::string& what);

}  // namespace cvtmesh
