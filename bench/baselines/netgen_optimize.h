// Netgen's volume optimizer (Debian's python3-netgen, Mesh.OptimizeVolumeMesh: combine, split,
// swap and smooth with Netgen's default MeshingParameters; boundary points and triangles kept) on
// an existing mesh: a peer column of `cvtmesh compare` and `cvtmesh bench` (issue 17). It runs
// bench/baselines/netgen_optimize.py in a child process (Netgen's C++ headers need an MPI build
// environment; its Python module is self-contained).
#pragma once
#include <string>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct NetgenResult {
  bool available = false;  // false: python3-netgen missing (the column is left out)
  std::string message;     // why it is not available
  double seconds = 0;      // Netgen's OptimizeVolumeMesh alone (the transfer not counted)
};

// Replaces `mesh`'s tets and interior vertices by Netgen's result (the boundary is checked to be
// unchanged: verify_peer). Throws InvariantError if Netgen fails or breaks the mesh.
NetgenResult netgen_optimize(TetMesh& mesh);

// The script's path: $CVTMESH_NETGEN_SCRIPT, else the copy of the source tree this was built from.
std::string netgen_script_path();

}  // namespace cvtmesh
