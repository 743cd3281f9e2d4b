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

}  // namespace cvtmesh
