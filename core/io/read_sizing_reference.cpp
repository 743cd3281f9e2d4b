#include "core/io/read_sizing_reference.h"

#include <filesystem>

#include "core/util/error.h"

namespace cvtmesh {

std::shared_ptr<const MeshData> read_sizing_reference(const std::string& path, int dim,
                                                      ReadOptions options) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError("sizing reference '" + path +
                     "': no such file (--sizing takes mesh, uniform, or a mesh or .geo file)");
  options.dim = dim;
  auto d = std::make_shared<MeshData>(read_mesh(path, options));
  const bool empty = d->dim == 3 ? d->tet.nb_tets() == 0 : d->tri.nb_tris() == 0;
  if (empty)
    throw InputError("sizing reference '" + path + "': no " +
                     (d->dim == 3 ? "tetrahedra" : "triangles") + " to take the sizes from");
  return d;
}

}  // namespace cvtmesh
