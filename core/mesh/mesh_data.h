// MeshData: what a reader returns and a writer takes — a 3D tet mesh or a 2D triangle mesh.
#pragma once
#include <string>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

struct MeshData {
  int dim = 0;  // 3: tet is used; 2: tri is used
  TetMesh tet;
  TriMesh2 tri;

  const ModelInfo& model() const { return dim == 3 ? tet.model : tri.model; }
  ModelInfo& model() { return dim == 3 ? tet.model : tri.model; }
};

// A per-element scalar field (one value per live tet in 3D, per live triangle in 2D, in element
// order), written as $ElementData in .msh and as cell data in VTK.
struct ElementField {
  std::string name;
  std::vector<double> values;
};

}  // namespace cvtmesh
