// A partitioned input's output partitioned again (ModelInfo::partitioning): the mesh of the
// current Gmsh model cut into as many parts by Gmsh's METIS (gmsh::model::mesh::partition), with
// ghost cells and the partition topology (the interfaces between parts as entities) if the input
// had them, in one file (Mesh.PartitionSplitMeshFiles 0). The element-to-part assignment is
// METIS's on this mesh: the input's only when METIS cuts the same mesh the same way (an
// unchanged mesh, e.g. cvtmesh convert), never for an optimized one. Requires a live GmshSession.
#pragma once
#include <cstdint>
#include <string>

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

struct Repartitioned {
  int nb_parts = 0;
  // Every cell of the input in the part it had there (and no other cell): Partitioning's
  // cell_tags and cell_parts against the parts Gmsh made.
  bool same_as_input = false;
  // The input file's own parts, its mesh unchanged (the file merged and written again).
  bool kept_input_file = false;
  // Written unpartitioned instead: Gmsh 4.8 could not read back the partitioned MSH 2.2 file
  // it wrote (core/io/write_mesh.cpp).
  bool unreadable_msh22 = false;
};

// A hash of the mesh (coordinates, cells, cell tags) and the stamp (size, modification time) of
// a file: whether a partitioned input reaches the writer unchanged (Partitioning).
std::uint64_t partition_fingerprint(const MeshData& data);
std::string file_stamp(const std::string& path);

// Partitions the current model (dim: its cells' dimension, 3 or 2). Throws InputError if Gmsh
// fails.
Repartitioned repartition_gmsh_model(const Partitioning& p, int dim);

// The note a front end prints for a partitioned input written to `path`: partitioned again (and
// whether as the input was), or, for a format without partitions, written unpartitioned.
std::string repartition_note(const Partitioning& p, const Repartitioned& r,
                             const std::string& path);

}  // namespace cvtmesh
