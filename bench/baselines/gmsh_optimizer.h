// Gmsh's own mesh optimizers applied to our mesh (the baselines of `cvtmesh compare`).
#pragma once
#include <string>

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// Runs gmsh::model::mesh::optimize(method, force, niter) on `data` loaded as a Gmsh model and
// reads the result back (entities, groups and boundary kept). method: "" (Gmsh's default tet
// optimizer), "Relocate3D", "Laplace2D", ... (Debian's Gmsh 4.8 has no Netgen/Mmg).
void gmsh_optimize_mesh(MeshData& data, const std::string& method = "", int niter = 1);

}  // namespace cvtmesh
