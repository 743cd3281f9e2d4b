#include "core/io/gmsh_surface_mesh3.h"

#include <gmsh.h>

#include <cstddef>
#include <unordered_map>
#include <string>
#include <vector>

#include "core/geometry/z_range.h"
#include "core/util/error.h"
#include "core/io/gmsh_model.h"
#include "core/io/gmsh_session.h"

namespace cvtmesh {

bool gmsh_surface_mesh_in_space() {
  gmsh::vectorpair ents;
  gmsh::model::getEntities(ents);
  for (const auto& [d, t] : ents) {
    if (d != 3) continue;
    std::vector<int> types;
    gmsh::model::mesh::getElementTypes(types, d, t);
    if (!types.empty()) return false;
  }
  // The corners of every 2D element (an order-2 element's mid-edge nodes are not its plane's).
  std::vector<std::size_t> all_tags;
  std::vector<double> all_xyz, par;
  gmsh::model::mesh::getNodes(all_tags, all_xyz, par, -1, -1, false, false);
  std::unordered_map<std::size_t, std::size_t> at;
  at.reserve(all_tags.size());
  for (std::size_t i = 0; i < all_tags.size(); ++i) at.emplace(all_tags[i], i);
  std::vector<double> corners;
  bool any = false;
  for (const auto& [d, t] : ents) {
    if (d != 2) continue;
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, d, t);
    for (std::size_t k = 0; k < types.size(); ++k) {
      std::string name;
      int edim = 0, order = 0, nn = 0, primary = 0;
      std::vector<double> local;
      gmsh::model::mesh::getElementProperties(types[k], name, edim, order, nn, local, primary);
      if (nn <= 0 || primary <= 0) continue;
      for (std::size_t e = 0; e < tags[k].size(); ++e)
        for (int j = 0; j < primary; ++j) {
          const auto it = at.find(nodes[k][nn * e + j]);
          if (it == at.end()) continue;
          corners.insert(corners.end(), &all_xyz[3 * it->second], &all_xyz[3 * it->second] + 3);
          any = true;
        }
    }
  }
  return any && !z_range(corners).planar;
}

MeshData surface_mesh_in_space(const SurfaceMesh& surface, const std::string& name,
                               const std::string& what) {
  if (surface.tris.empty()) throw InputError(what + " contains no triangles");
  GmshSession session;
  std::string previous;
  gmsh::model::getCurrent(previous);
  MeshData data;
  auto restore = [&] {
    gmsh::model::remove();
    if (!previous.empty() && !session.owns()) gmsh::model::setCurrent(previous);
  };
  try {
    gmsh_checked("cannot read the surface of " + what, [&] {
      gmsh::model::add(name);
      gmsh::model::addDiscreteEntity(2, 1);
      const std::size_t nv = surface.xyz.size() / 3, nf = surface.tris.size() / 3;
      std::vector<std::size_t> node_tags(nv), elem_tags(nf), conn(surface.tris.size());
      for (std::size_t i = 0; i < nv; ++i) node_tags[i] = i + 1;
      for (std::size_t f = 0; f < nf; ++f) elem_tags[f] = f + 1;
      for (std::size_t i = 0; i < conn.size(); ++i)
        conn[i] = static_cast<std::size_t>(surface.tris[i]) + 1;
      gmsh::model::mesh::addNodes(2, 1, node_tags, surface.xyz);
      gmsh::model::mesh::addElementsByType(1, 2, elem_tags, conn);
    });
    data = mesh_from_gmsh(-1, what);
  } catch (...) {
    restore();
    throw;
  }
  restore();
  return data;
}

}  // namespace cvtmesh
