#include "core/io/quality_view_geo.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "core/io/camera_cut.h"
#include "core/mesh/check_surface_mesh.h"

namespace cvtmesh {

void finite_range(const ElementField& field, double& lo, double& hi) {
  lo = hi = 0;
  bool any = false;
  for (double v : field.values)
    if (std::isfinite(v)) {
      lo = any ? std::min(lo, v) : v;
      hi = any ? std::max(hi, v) : v;
      any = true;
    }
  if (hi <= lo) hi = lo + 1e-6;
}

std::string quality_view_geo(const MeshData& data, const std::vector<ElementField>& fields,
                             const std::string& first_view) {
  if (fields.empty()) return {};
  double lo = 0, hi = 0;
  finite_range(fields.front(), lo, hi);
  const std::string v = "View[" + first_view;
  char buf[160];
  std::snprintf(buf, sizeof buf, "].CustomMin = %.17g;\n", lo);
  std::string s = v + "].RangeType = 2;\n" + v + buf;
  std::snprintf(buf, sizeof buf, "].CustomMax = %.17g;\n", hi);
  s += v + buf;
  for (std::size_t k = 1; k < fields.size(); ++k)
    s += v + " + " + std::to_string(k) + "].Visible = 0;\n";
  // A surface mesh in space is seen whole (its triangles are its elements: no cut).
  if (data.dim == 3 && data.tet.nb_vertices() > 0 && !is_surface_mesh(data.tet)) {
    std::array<double, 3> lo3, hi3;
    for (int k = 0; k < 3; ++k) lo3[k] = hi3[k] = data.tet.point(0)[k];
    for (int p = 0; p < data.tet.nb_vertices(); ++p)
      for (int k = 0; k < 3; ++k) {
        lo3[k] = std::min(lo3[k], data.tet.point(p)[k]);
        hi3[k] = std::max(hi3[k], data.tet.point(p)[k]);
      }
    s += camera_cut_geo({0.5 * (lo3[0] + hi3[0]), 0.5 * (lo3[1] + hi3[1]), 0.5 * (lo3[2] + hi3[2])},
                        first_view);
  }
  return s;
}

}  // namespace cvtmesh
