// Coordinates as a text writer stores them: rounded to `digits` significant decimal digits
// (Gmsh's ASCII .msh: 16, "%.16g"). An output is verified as it will be read back: a tet that is
// positive in memory by a few ulps can be flat once written (four nearly coplanar vertices).
#pragma once
#include <vector>

namespace cvtmesh {

double round_to_digits(double x, int digits);

// xyz: #V by 3. Rounds the coordinates of the vertices flagged in `which` (#V; empty: all).
void round_coordinates(std::vector<double>& xyz, int digits, const std::vector<char>& which = {});

}  // namespace cvtmesh
