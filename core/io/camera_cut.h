// The cut through a 3D model that faces the camera, as Gmsh's clip plane 0: what the GUI, the
// ONELAB client and the companion .opt of `optimize --quality` use to show the quality inside a
// volume mesh. Gmsh keeps the points with A x + B y + C z + D >= 0 (General.Clip0A..D); the cut
// keeps the half of the model away from the camera, so that the plane is seen face on.
#pragma once
#include <array>
#include <string>

namespace cvtmesh {

// The unit vector from the model toward the camera, in model coordinates, for Gmsh's view angles
// General.RotationX/Y/Z (degrees; the model-view rotation is Rx * Ry * Rz, the camera looks along
// -z in eye coordinates): the third row of that rotation. (0, 0, 1) for Gmsh's default view.
std::array<double, 3> camera_direction(double rx_deg, double ry_deg, double rz_deg);

// {A, B, C, D} of the plane through `centre` normal to `toward_camera`, keeping the far half.
std::array<double, 4> camera_cut_plane(const std::array<double, 3>& toward_camera,
                                       const std::array<double, 3>& centre);

// The same in Gmsh's .geo language, evaluated by Gmsh from its current view angles when it reads
// the text (a .opt merged with a .msh, or text a ONELAB client sends): sets the clip plane through
// `centre`, whole elements, and clips the mesh and the view whose index is the .geo expression
// `view` (e.g. "0" or "cvt_q"). One statement per line.
std::string camera_cut_geo(const std::array<double, 3>& centre, const std::string& view);

}  // namespace cvtmesh
