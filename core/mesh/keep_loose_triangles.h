// Surface triangles that are not a face of any tet — a surface that bounds no volume (t2.geo's
// "My surface"), a discrete surface added inside a volume (t14.geo's homology chains) — are not
// constraints of the tet mesh: they move from mesh.tris to mesh.model.extra (one block per
// surface entity, Gmsh type 2, tags kept), where they are written back unchanged.
#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// Returns the number of triangles moved. The adjacency need not be built.
int keep_loose_triangles(TetMesh& mesh);

}  // namespace cvtmesh
