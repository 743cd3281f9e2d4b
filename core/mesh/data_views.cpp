#include "core/mesh/data_views.h"

#include "core/mesh/mesh_data.h"

namespace cvtmesh {
namespace {

void mix(std::uint64_t& h, const void* data, std::size_t bytes) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ULL;
}

}  // namespace

std::uint64_t mesh_fingerprint(const MeshData& data) {
  std::uint64_t h = 1469598103934665603ULL;
  const std::vector<double>& xyz = data.dim == 3 ? data.tet.xyz : data.tri.xy;
  const std::vector<int>& cells = data.dim == 3 ? data.tet.tets : data.tri.tris;
  const std::size_t npe = data.dim == 3 ? 4 : 3;
  mix(h, xyz.data(), xyz.size() * sizeof(double));
  for (std::size_t c = 0; c + npe <= cells.size(); c += npe)
    if (cells[c] >= 0) mix(h, &cells[c], npe * sizeof(int));
  return h ^ (xyz.size() * 31 + cells.size());
}

std::size_t nb_live_cells(const MeshData& data) {
  const std::vector<int>& cells = data.dim == 3 ? data.tet.tets : data.tri.tris;
  const std::size_t npe = data.dim == 3 ? 4 : 3;
  std::size_t n = 0;
  for (std::size_t c = 0; c + npe <= cells.size(); c += npe) n += cells[c] >= 0;
  return n;
}

}  // namespace cvtmesh
