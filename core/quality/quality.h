// Element quality measures: pure functions of the vertex coordinates, selected by one enum
// (Gmsh qmTetrahedron style). Inverted elements get a negative value for the shape measures,
// never a silent 0.
#pragma once
#include <array>
#include <string>

namespace cvtmesh {

enum class Measure {
  kQ,  // tet: 72*sqrt(3)*V/(sum L^2)^(3/2); tri: 4*sqrt(3)*A/sum L^2 (the paper's). 1 = regular
  kRadiusRatio,  // tet: 3r/R; tri: 2r/R. 1 = regular. (Gmsh 4.8's "gamma" for tets.)
  kMinAngle,     // tet: minimum dihedral angle; tri: minimum angle. Degrees.
  kMaxAngle,     // tet: maximum dihedral angle; tri: maximum angle. Degrees.
  kGmshIcn,      // Gmsh's inverse condition number (Plugin(AnalyseMeshQuality) ICNMeasure)
  // The element's explicit time step, P1 with lumped mass, wave speed 1 (element_time_step.h).
  // Larger is better; not scale-invariant (it scales with the element's size).
  kTimeStep,
};

// Parses "q", "radius-ratio", "min-angle", "max-angle", "icn", "time-step"; throws
// std::invalid_argument.
Measure measure_from_string(const std::string& name);
std::string measure_name(Measure m);

// Tetrahedron a,b,c,d (each 3 doubles). Positive orientation = positive volume. Bitwise the same
// value for every orientation-preserving order of the four vertices (even permutations).
double tet_quality(const double* a, const double* b, const double* c, const double* d, Measure m);
// The four measures of the quality tables at once (Q, radius ratio, min and max dihedral angle in
// degrees), each bitwise tet_quality's, for the cost of about one.
std::array<double, 4> tet_table_qualities(const double* a, const double* b, const double* c,
                                          const double* d);
// Triangle a,b,c; dim = 2 (x,y; counter-clockwise positive) or 3 (x,y,z; always >= 0).
double tri_quality(const double* a, const double* b, const double* c, int dim, Measure m);
// tri_quality's kMinAngle and kMaxAngle at once, each bitwise its, for the cost of one.
std::array<double, 2> tri_min_max_angle(const double* a, const double* b, const double* c, int dim);

}  // namespace cvtmesh
