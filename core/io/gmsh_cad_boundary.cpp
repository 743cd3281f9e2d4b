#include "core/io/gmsh_cad_boundary.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "core/mesh/bounding_box.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

class GmshCadGeometry final : public BoundaryGeometry {
 public:
  std::vector<int> surfaces;      // every surface tag of the model
  std::vector<double> reference;  // samples of the input boundary, projected on the CAD

  bool closest(int dim, int tag, const double* p, double* q) const {
    try {
      // The projection's own point (in Gmsh 4.8.4 the parametric coordinates it returns for an
      // OpenCASCADE surface are not reliable: getValue at them can give another point).
      std::vector<double> c, par;
      gmsh::model::getClosestPoint(dim, tag, {p[0], p[1], p[2]}, c, par);
      if (c.size() < 3) return false;
      for (int d = 0; d < 3; ++d) q[d] = c[d];
      return true;
    } catch (...) {
      return false;
    }
  }
  bool closest_on_surface(int s, const double* p, double* q) const override {
    return closest(2, s, p, q);
  }
  bool closest_on_curve(int c, const double* p, double* q) const override {
    return closest(1, c, p, q);
  }
  // One getClosestPoint per surface of the model: slow (optimize() measures on the input
  // triangulation instead, core/pipeline/measure_on_input_boundary.h).
  double distance_to_boundary(const double* p) const override {
    double best = std::numeric_limits<double>::infinity();
    for (int s : surfaces) {
      double q[3];
      if (closest(2, s, p, q))
        best =
            std::min(best, std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                     (p[2] - q[2]) * (p[2] - q[2])));
    }
    return best;
  }
  std::vector<double> samples() const override { return reference; }
  const char* kind() const override { return "cad"; }
  bool thread_safe() const override { return false; }
};

bool is_cad(int dim, int tag) {
  std::string type;
  gmsh::model::getType(dim, tag, type);
  return type.rfind("Discrete", 0) != 0 && type != "Unknown";
}

}  // namespace

bool gmsh_model_has_cad(const TetMesh& m) {
  try {
    std::set<std::pair<int, int>> ents;
    for (const VertexClass& c : m.vclass)
      if (c.dim == 1 || c.dim == 2) ents.insert({c.dim, c.entity});
    for (const auto& [d, t] : ents)
      if (!is_cad(d, t)) return false;
    return !ents.empty();
  } catch (...) {
    return false;
  }
}

BoundaryModel make_gmsh_cad_boundary(const TetMesh& m, const BoundaryModelOptions& o) {
  if (!gmsh_model_has_cad(m))
    throw InputError("the current Gmsh model has no CAD entities for this mesh's boundary");
  auto g = std::make_shared<GmshCadGeometry>();
  gmsh::vectorpair surfs;
  gmsh::model::getEntities(surfs, 2);
  for (const auto& [d, t] : surfs) g->surfaces.push_back(t);
  // Periodic entities: their nodes stay fixed.
  std::set<std::pair<int, int>> periodic;
  for (int dim = 1; dim <= 2; ++dim) {
    gmsh::vectorpair ents;
    gmsh::model::getEntities(ents, dim);
    for (const auto& [d, t] : ents) {
      int master = t;
      std::vector<std::size_t> nodes, masters;
      std::vector<double> affine;
      try {
        gmsh::model::mesh::getPeriodicNodes(d, t, master, nodes, masters, affine, false);
      } catch (...) {
        continue;
      }
      if (master != t && !nodes.empty()) {
        periodic.insert({d, t});
        periodic.insert({d, master});
      }
    }
  }
  BoundaryModel out;
  out.role.assign(static_cast<std::size_t>(m.nb_vertices()), VertexRole{});
  std::vector<char> locked(out.role.size(), 0);
  for (int f = 0; f < m.nb_tris(); ++f)
    if (std::find(o.locked_surfaces.begin(), o.locked_surfaces.end(), m.tri_surface[f]) !=
            o.locked_surfaces.end() ||
        periodic.count({2, m.tri_surface[f]}))
      for (int k = 0; k < 3; ++k) locked[m.tris[3 * f + k]] = 1;
  for (int v = 0; v < m.nb_vertices(); ++v) {
    const VertexClass c = m.vclass[v];
    VertexRole& r = out.role[v];
    if (c.dim == 3) continue;
    const bool lock = locked[v] || periodic.count({c.dim, c.entity}) ||
                      (c.dim == 1 && std::find(o.locked_curves.begin(), o.locked_curves.end(),
                                               c.entity) != o.locked_curves.end());
    if (c.dim == 2 && !lock) {
      r = {BoundaryRole::kSurface, c.entity};
      ++out.nb_surface_vertices;
    } else if (c.dim == 1 && !lock) {
      r = {BoundaryRole::kCurve, c.entity};
      ++out.nb_curve_vertices;
    } else {
      r.role = BoundaryRole::kFixed;
      ++out.nb_fixed_vertices;
    }
  }
  // Reference samples: the input boundary's vertices and triangle centroids, projected on their
  // surface. The input's own distance to the CAD (its chord error): at the centroids and the
  // edge midpoints.
  auto dist = [](const double* a, const double* b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                     (a[2] - b[2]) * (a[2] - b[2]));
  };
  double deviation = 0;
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* w = &m.tris[3 * static_cast<std::size_t>(f)];
    double c[3];
    for (int d = 0; d < 3; ++d) c[d] = (m.point(w[0])[d] + m.point(w[1])[d] + m.point(w[2])[d]) / 3;
    double q[3];
    if (g->closest_on_surface(m.tri_surface[f], c, q)) {
      g->reference.insert(g->reference.end(), q, q + 3);
      deviation = std::max(deviation, dist(c, q));
    }
    g->reference.insert(g->reference.end(), m.point(w[0]), m.point(w[0]) + 3);
    for (int k = 0; k < 3; ++k) {
      const int a = w[k], b = w[(k + 1) % 3];
      if (a > b) continue;  // each interior edge once (a boundary edge of a patch: maybe twice)
      double mid[3];
      for (int d = 0; d < 3; ++d) mid[d] = 0.5 * (m.point(a)[d] + m.point(b)[d]);
      if (g->closest_on_surface(m.tri_surface[f], mid, q))
        deviation = std::max(deviation, dist(mid, q));
    }
  }
  out.reference_deviation = deviation;
  out.geometry = g;
  out.diagonal = bounding_box_diagonal(m);
  out.input_xyz = m.xyz;
  return out;
}

BoundaryModel make_gmsh_cad_boundary_if_cad(const TetMesh& m, const BoundaryModelOptions& o) {
  if (!gmsh_model_has_cad(m)) return {};
  return make_gmsh_cad_boundary(m, o);
}

}  // namespace cvtmesh
