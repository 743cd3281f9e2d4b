// The $MeshFormat of a .msh file (version, binary or ASCII), so that an output is written in the
// input's format by default.
#pragma once
#include <string>

namespace cvtmesh {

struct MshFormat {
  bool ok = false;  // false: not a .msh, unreadable, or no $MeshFormat line
  double version = 4.1;
  bool binary = false;
};

MshFormat read_msh_format(const std::string& path);

// The number of parts the $PartitionedEntities section of a MSH 4 file declares (ASCII or
// binary; a file of a mesh saved one file per part declares them all), 0 if it has none.
int read_msh_partition_count(const std::string& path);

// Whether the .msh file holds some section more than once ($Entities, $Nodes, $Elements, ...)
// and every repeat is byte for byte the same as the first: the mesh written again in front of a
// view (Gmsh's view.write with append and PostProcessing.SaveMesh = 1, its default). Gmsh reads
// such a file keeping the first copy and logging the duplicates. False if no section repeats,
// a repeat differs, or the file cannot be read.
bool msh_repeats_identical_sections(const std::string& path);

}  // namespace cvtmesh
