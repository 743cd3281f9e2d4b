// Tetrahedralizing the inside of a closed triangulated surface with Gmsh.
#pragma once
#include <string>
#include <vector>

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
// Connected components of the triangles (through shared edges): the component of each triangle;
// nb_shells is set to their number.
std::vector<int> shells_of(const SurfaceMesh& s, int& nb_shells);

// True if every edge lies on an even number of triangles (and there is one).
bool surface_closes_up(const SurfaceMesh& s);

// The triangles of each shell turned to one orientation (nest_shells' winding numbers need it; a
// mesh file's surfaces are oriented each its own way): a breadth-first walk over shared edges
// flips a neighbour that runs a shared edge the same way.
void orient_shells(SurfaceMesh& s);

// The nesting of closed shells (shell[f]: the shell of triangle f, nb shells): depth[i] = the
// number of shells around shell i (winding number of one of its vertices), parent[i] = the
// innermost of them (-1 if none). A shell of odd depth is a cavity of its parent.
void nest_shells(const SurfaceMesh& s, const std::vector<int>& shell, int nb,
                 std::vector<int>& depth, std::vector<int>& parent);

// generate(3) on the current Gmsh model with the meshing options of `options` (optimizer, size
// factor, seed), one thread.
void generate_volumes(const ReadOptions& options);

MeshData tetrahedralize_surface(const SurfaceMesh& surface, const std::string& what,
                                const ReadOptions& options = {});

}  // namespace cvtmesh
