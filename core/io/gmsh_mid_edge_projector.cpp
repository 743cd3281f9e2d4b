#include "core/io/gmsh_mid_edge_projector.h"

#include <gmsh.h>

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cvtmesh {

MidEdgeProjector gmsh_cad_mid_edge_projector() {
  auto cad = std::make_shared<std::map<std::pair<int, int>, bool>>();
  return [cad](int dim, int tag, const double* p, double* out) {
    try {
      auto it = cad->find({dim, tag});
      if (it == cad->end()) {
        std::string type;
        gmsh::model::getType(dim, tag, type);
        const bool yes = type.rfind("Discrete", 0) != 0 && type != "Unknown" && !type.empty();
        it = cad->emplace(std::make_pair(dim, tag), yes).first;
      }
      if (!it->second) return false;
      std::vector<double> c, par;
      gmsh::model::getClosestPoint(dim, tag, {p[0], p[1], p[2]}, c, par);
      if (c.size() < 3) return false;
      for (int d = 0; d < 3; ++d) out[d] = c[d];
      return true;
    } catch (...) {
      return false;
    }
  };
}

}  // namespace cvtmesh
