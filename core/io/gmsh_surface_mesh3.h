// A mesh of triangles on surfaces in space that bound no volume (an open shell, CAD faces, a
// BEM or shell-FE mesh, a plate in the plane x = 0): read as a surface mesh in 3D, a TetMesh
// without tets whose `tris` are the surface (core/mesh/tet_mesh.h), optimized on its surfaces
// (core/boundary/optimize_surface_mesh.h) instead of being refused as a non-planar 2D mesh.
#pragma once

namespace cvtmesh {

// True if the current Gmsh model's highest elements are 2D and their corner nodes are not all in
// one plane z = const (z_range.h): not a 2D mesh, a surface mesh in space. Requires a live
// GmshSession.
bool gmsh_surface_mesh_in_space();

}  // namespace cvtmesh
