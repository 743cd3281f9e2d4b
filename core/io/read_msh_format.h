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

}  // namespace cvtmesh
