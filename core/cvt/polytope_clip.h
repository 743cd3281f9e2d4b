// A convex polytope (unique vertices + faces as index cycles, flat arrays) clipped by half-spaces,
// and its moments. Used to build Voronoi cells restricted to a tet (cell ∩ tet = tet clipped by
// the bisector half-spaces). Reused buffers: no allocation in the hot loop once warmed up.
#pragma once
#include <array>
#include <vector>

#include "core/geometry/vec3.h"

namespace cvtmesh {

struct Polytope {
  std::vector<Vec3> vtx;        // vertices (each stored once)
  std::vector<int> fv;          // the faces' vertex indices, face after face, counterclockwise
                                // seen from outside
  std::vector<int> face_start;  // #faces + 1 offsets into fv
  std::vector<int> face_id;     // who made the face: 0..3 = tet faces, >= 4 = clip planes
  // Work arrays of the clipper (kept here to be reused).
  std::vector<double> sd;
  std::vector<int> remap, next;
  std::vector<std::array<int, 3>> cut;  // (lower, upper, new vertex) of each edge cut
  int nb_faces() const { return static_cast<int>(face_id.size()); }
  void clear() {
    vtx.clear();
    fv.clear();
    face_start.assign(1, 0);
    face_id.clear();
  }
};

// The tetrahedron p0..p3 (positively oriented) as a polytope; face f (opposite vertex f) has id f.
void tet_polytope(const double* p0, const double* p1, const double* p2, const double* p3,
                  Polytope& out);

// Keeps the part {x : n.x <= d}; the new face gets `id`. `scratch` is a work buffer. Returns false
// if nothing (of positive volume) is left. `eps`: points within eps of the plane count as on it.
bool clip_polytope(Polytope& p, const Vec3& n, double d, int id, double eps, Polytope& scratch);
// The same with the tolerance given as tol = eps * |n| (the clip of a Voronoi cell applies each
// bisector to many pieces: its norm is taken once), and `changed` set to whether the polytope
// changed (false: no vertex beyond the plane, the polytope kept as it was).
bool clip_polytope_tol(Polytope& p, const Vec3& n, double d, int id, double tol, Polytope& scratch,
                       bool& changed);

// Moments relative to an origin z: m0 = volume, m1 = int (x - z), m2 = int (x - z)(x - z)^T.
struct Moments {
  double m0 = 0;
  Vec3 m1{0, 0, 0};
  std::array<double, 9> m2{};  // row-major 3x3
  void add(const Moments& o);
};
Moments polytope_moments(const Polytope& p, const Vec3& z);

// Area of the faces with the given id (0 if the face is gone).
double face_area(const Polytope& p, int id);

}  // namespace cvtmesh
