// Geometry of one tetrahedron / triangle from its vertex coordinates. Pure functions.
#pragma once
#include <array>

#include "core/geometry/vec3.h"

namespace cvtmesh {

// Signed volume (b-a).((c-a)x(d-a))/6 (floating point; use orient3d for decisions).
double tet_volume(const double* a, const double* b, const double* c, const double* d);
// Circumcentre of the tetrahedron (undefined for a flat one: returns the centroid then).
Vec3 tet_circumcenter(const double* a, const double* b, const double* c, const double* d);
// Circumradius and inradius.
double tet_circumradius(const double* a, const double* b, const double* c, const double* d);
double tet_inradius(const double* a, const double* b, const double* c, const double* d);
// The six interior dihedral angles (radians), at the edges in kTetEdge order.
std::array<double, 6> tet_dihedral_angles(const double* a, const double* b, const double* c,
                                          const double* d);
// Their cosines, clamped to [-1, 1] (tet_dihedral_angles is acos of each): the smallest angle is
// acos of the largest cosine, without the five other acos.
std::array<double, 6> tet_dihedral_cosines(const double* a, const double* b, const double* c,
                                           const double* d);
// Sum of the squared edge lengths and the longest edge.
double tet_sum_sq_edges(const double* a, const double* b, const double* c, const double* d);

// Signed area of a planar triangle (x,y), counter-clockwise positive.
double tri_area2d(const double* a, const double* b, const double* c);
// Area of a triangle in 3D (unsigned).
double tri_area3d(const double* a, const double* b, const double* c);
// The three interior angles (radians) at a, b, c; works in 2D (dim=2) and 3D (dim=3) coordinates.
std::array<double, 3> tri_angles(const double* a, const double* b, const double* c, int dim);
// Circumcentre of a 2D triangle.
std::array<double, 2> tri_circumcenter2d(const double* a, const double* b, const double* c);
// Circumcentre of a triangle in 3D (in its plane).
Vec3 tri_circumcenter3d(const double* a, const double* b, const double* c);

}  // namespace cvtmesh
