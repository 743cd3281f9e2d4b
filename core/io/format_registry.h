// Readers and writers of our own (non-Gmsh) formats, looked up by lower-case extension.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

using MeshReader = std::function<MeshData(const std::string& path)>;
// Writes `data` to `path` (the temporary of the target, same extension). Formats made of several
// files (TetGen .node/.ele/.face) are handled by write_mesh itself.
using MeshWriter = std::function<void(const MeshData& data, const std::string& path,
                                      const std::vector<ElementField>& fields)>;

const MeshReader* find_reader(const std::string& ext);
const MeshWriter* find_writer(const std::string& ext);
std::vector<std::string> own_write_extensions();

}  // namespace cvtmesh
