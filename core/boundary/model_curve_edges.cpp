#include "core/boundary/model_curve_edges.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <map>
#include <vector>

namespace cvtmesh {
namespace {

// A vertex's class, through pin_vertices' encoding (entity -1 - (4 entity + dim), dim 0).
VertexClass decoded(VertexClass c) {
  if (c.entity >= 0) return c;
  const int x = -1 - c.entity;
  return VertexClass{static_cast<std::int8_t>(x % 4), x / 4};
}

}  // namespace

bool set_model_curve_edges(const TetMesh& mesh, BoundaryModel& model) {
  // The curves bounded by each point.
  std::map<int, std::vector<int>> curves_of_point;
  bool any_curve = false;
  for (const ModelEntity& e : mesh.model.entities) {
    if (e.dim != 1) continue;
    any_curve = true;
    for (int p : e.boundary) curves_of_point[std::abs(p)].push_back(e.tag);
  }
  if (!any_curve) return false;
  for (auto& [p, c] : curves_of_point) std::sort(c.begin(), c.end());
  const int nv = mesh.nb_vertices();
  // The curves holding v (sorted); unknown: any curve may.
  auto curves = [&](int v, std::vector<int>& out, bool& unknown) {
    out.clear();
    unknown = false;
    if (v >= static_cast<int>(mesh.vclass.size())) {
      unknown = true;
      return;
    }
    const VertexClass c = decoded(mesh.vclass[v]);
    if (c.dim == 1) {
      if (c.entity == 0) unknown = true;
      out.push_back(c.entity);
    } else if (c.dim == 0) {
      const auto it = curves_of_point.find(c.entity);
      if (c.entity == 0 || it == curves_of_point.end())
        unknown = true;
      else
        out = it->second;
    }
  };
  std::vector<std::array<int, 2>> edges;
  std::vector<int> ca, cb, common;
  for (int f = 0; f < mesh.nb_tris(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.tris[3 * static_cast<std::size_t>(f) + k],
                b = mesh.tris[3 * static_cast<std::size_t>(f) + (k + 1) % 3];
      if (a < 0 || b < 0 || a >= nv || b >= nv) continue;
      const VertexClass x = decoded(mesh.vclass[a]), y = decoded(mesh.vclass[b]);
      if (x.dim > 1 || y.dim > 1) continue;
      bool ua, ub;
      curves(a, ca, ua);
      curves(b, cb, ub);
      common.clear();
      std::set_intersection(ca.begin(), ca.end(), cb.begin(), cb.end(), std::back_inserter(common));
      if (ua || ub || !common.empty()) edges.push_back({std::min(a, b), std::max(a, b)});
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  model.curve_edges = std::move(edges);
  model.curve_edges_known = true;
  return true;
}

}  // namespace cvtmesh
