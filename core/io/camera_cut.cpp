#include "core/io/camera_cut.h"

#include <cmath>
#include <cstdio>

namespace cvtmesh {

std::array<double, 3> camera_direction(double rx_deg, double ry_deg, double rz_deg) {
  const double d = M_PI / 180;
  const double A = std::cos(rx_deg * d), B = std::sin(rx_deg * d);
  const double C = std::cos(ry_deg * d), D = std::sin(ry_deg * d);
  const double E = std::cos(rz_deg * d), F = std::sin(rz_deg * d);
  // Third row of Rx(x) Ry(y) Rz(z).
  return {-A * D * E + B * F, A * D * F + B * E, A * C};
}

std::array<double, 4> camera_cut_plane(const std::array<double, 3>& n,
                                       const std::array<double, 3>& c) {
  // Keep n . (p - c) <= 0:  -n . p + n . c >= 0.
  return {-n[0], -n[1], -n[2], n[0] * c[0] + n[1] * c[1] + n[2] * c[2]};
}

std::string camera_cut_geo(const std::array<double, 3>& c, const std::string& view) {
  char centre[160];
  std::snprintf(centre, sizeof centre, "cvt_cx = %.17g;\ncvt_cy = %.17g;\ncvt_cz = %.17g;\n", c[0],
                c[1], c[2]);
  // camera_direction, in Gmsh's language.
  std::string s =
      "// The cut through the centre that faces the camera (cvtmesh, core/io/camera_cut.h).\n";
  s += centre;
  s += "cvt_a = General.RotationX * Pi / 180;\ncvt_b = General.RotationY * Pi / 180;\n"
       "cvt_c = General.RotationZ * Pi / 180;\n"
       "cvt_nx = -Cos(cvt_a) * Sin(cvt_b) * Cos(cvt_c) + Sin(cvt_a) * Sin(cvt_c);\n"
       "cvt_ny = Cos(cvt_a) * Sin(cvt_b) * Sin(cvt_c) + Sin(cvt_a) * Cos(cvt_c);\n"
       "cvt_nz = Cos(cvt_a) * Cos(cvt_b);\n"
       "General.Clip0A = -cvt_nx;\nGeneral.Clip0B = -cvt_ny;\nGeneral.Clip0C = -cvt_nz;\n"
       "General.Clip0D = cvt_nx * cvt_cx + cvt_ny * cvt_cy + cvt_nz * cvt_cz;\n"
       "General.ClipWholeElements = 1;\nMesh.Clip = 1;\n";
  s += "View[" + view + "].Clip = 1;\n";
  return s;
}

}  // namespace cvtmesh
