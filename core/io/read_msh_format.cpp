#include "core/io/read_msh_format.h"

#include <fstream>

namespace cvtmesh {

MshFormat read_msh_format(const std::string& path) {
  MshFormat f;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int i = 0; i < 8 && std::getline(in, line); ++i) {
    if (line.rfind("$MeshFormat", 0) != 0) continue;
    int file_type = 0, data_size = 0;
    if (!(in >> f.version >> file_type >> data_size)) return MshFormat{};
    f.binary = file_type == 1;
    f.ok = true;
    return f;
  }
  return f;
}

}  // namespace cvtmesh
