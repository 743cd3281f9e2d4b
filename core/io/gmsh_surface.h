// Tetrahedralizing the inside of a closed triangulated surface with Gmsh.
#pragma once
#include <string>

#include "core/mesh/mesh_data.h"
#include "core/io/read_mesh.h"
#include "core/io/surface_io.h"

namespace cvtmesh {

// Builds a Gmsh model from the surface (a discrete surface per connected shell, surface loops,
// volumes: a shell nested in an odd number of others is a cavity of the innermost one around it),
// meshes the volumes (generate(3), with the meshing options of `options`: optimizer, size
// factor, seed) and returns the tet mesh (shell i is surface i, volumes are numbered from 1; the
// surface triangles are kept as they are). The current Gmsh model, if any, is left current
// afterwards. Throws InputError("<what>: ...") if Gmsh cannot mesh it (self-intersecting
// surface...).
MeshData tetrahedralize_surface(const SurfaceMesh& surface, const std::string& what,
                                const ReadOptions& options = {});

}  // namespace cvtmesh
