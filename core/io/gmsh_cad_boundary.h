// The CAD reference geometry of the current Gmsh model (BoundaryGeometry through the Gmsh SDK:
// gmsh::model::getClosestPoint: the kernel's orthogonal projection; in 4.8.4 the parameters it
// returns for OpenCASCADE surfaces are not reliable, so getValue is not used). Available while the
// model's CAD is loaded in this process: the in-process front ends (gmsh_optimize for C++ and
// Python, the GUI panel) and `cvtmesh optimize` on a model file Gmsh meshes itself (.geo, .step,
// .brep, ...) pass make_gmsh_cad_boundary_if_cad as OptimizeOptions::boundary_model; a .msh or a
// surface file has no CAD and gets the discrete geometry. Every Gmsh call stays in core/io/.
#pragma once
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// True if every surface and curve entity the mesh's boundary vertices are classified on is a CAD
// entity of the current model (not "Discrete ..."), so that the CAD geometry applies. Requires a
// live GmshSession with the model current.
bool gmsh_model_has_cad(const TetMesh& mesh);

// Roles from the classification: a vertex of class dim 2 moves on its Gmsh surface, dim 1 slides
// along its Gmsh curve, dim 0 is fixed, as are the vertices of locked surfaces / curves and of
// periodic entities (gmsh::model::mesh::getPeriodicNodes). Entity ids of the geometry are the Gmsh
// tags. Queries are serial (thread_safe() is false). Throws InputError if the model has no CAD.
BoundaryModel make_gmsh_cad_boundary(const TetMesh& mesh, const BoundaryModelOptions& options = {});

// make_gmsh_cad_boundary if gmsh_model_has_cad(mesh), else an empty BoundaryModel (no geometry:
// optimize() then uses the discrete geometry of the input). For OptimizeOptions::boundary_model.
BoundaryModel make_gmsh_cad_boundary_if_cad(const TetMesh& mesh,
                                            const BoundaryModelOptions& options);

}  // namespace cvtmesh
