// The post-processing views of an input file (Gmsh's $NodeData / $ElementData, model-based):
// kept with the mesh they belong to, carried onto the optimized mesh (transfer_views.h) and
// written back with it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace cvtmesh {

struct MeshData;

struct DataView {
  std::string name;
  bool on_nodes = true;       // NodeData: per vertex; ElementData: per live simplex of the mesh
                              // dimension, in element order (as ElementField)
  int components = 1;         // 1 scalar, 3 vector, 9 tensor
  std::vector<double> times;  // one per step
  std::vector<std::vector<double>> steps;  // per step: components values per vertex / simplex;
                                           // NaN where the file had none
  // mesh_fingerprint of the mesh the values belong to: a writer writes the view only with it.
  std::uint64_t fingerprint = 0;
};

// A hash of the mesh's coordinates and live simplices of its dimension (3D tets, 2D triangles).
std::uint64_t mesh_fingerprint(const MeshData& data);

// Number of live simplices of the mesh dimension.
std::size_t nb_live_cells(const MeshData& data);

}  // namespace cvtmesh
