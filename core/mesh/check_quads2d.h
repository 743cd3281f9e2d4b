// Validity of the kept quadrangles of a planar mesh (kept_quads.h): each must be strictly convex
// in the turning sense of its surface — the 4 triangles of consecutive corners (q0 q1 q2, q1 q2
// q3, q2 q3 q0, q3 q0 q1) positive by exact orient2d. A quadrangle with one of them not positive
// is inverted (its signed area is not positive) or not convex (a reflex, flat or folded corner).
// What `cvtmesh check` reports (exit 5), and what the quadrangle smoothing keeps.
#pragma once
#include <string>
#include <vector>

#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

// True if the quadrangle a, b, c, d (2 doubles each) is strictly convex and counter-clockwise.
bool quad_strictly_convex(const double* a, const double* b, const double* c, const double* d);

struct QuadCheck {
  long nb_quads = 0;
  long nb_inverted = 0;               // signed area <= 0 in their surface's turning sense
  long nb_not_convex = 0;             // positive area, but a corner reflex or flat
  std::vector<std::string> problems;  // the first few, by Gmsh element tag
  bool ok() const { return nb_inverted == 0 && nb_not_convex == 0; }
};

QuadCheck check_quads2d(const TriMesh2& mesh);

}  // namespace cvtmesh
