// How far one element falls short of a reference mesh's worst values (the per-region "never worse
// than the input" of optimize()): 0 if its Q is at least ref.q_min, its minimum angle at least
// ref.min_angle and its maximum angle at most ref.max_angle (dihedral angles in 3D, planar in 2D,
// degrees), else the sum of the shortfalls, the angles' divided by 180. Pure; the same measures
// (tet_quality / tri_quality) as quality_stats, so a mesh whose elements all have shortfall 0 has
// none of worse_than's three minima worse than the reference.
#pragma once
#include "core/quality/quality_stats.h"

namespace cvtmesh {

double element_shortfall(double q, double min_angle, double max_angle, const QualityStats& ref);
// Tet a,b,c,d (3 doubles each, positively oriented).
double tet_shortfall(const double* a, const double* b, const double* c, const double* d,
                     const QualityStats& ref);
// Planar triangle a,b,c (2 doubles each, counter-clockwise).
double tri_shortfall(const double* a, const double* b, const double* c, const QualityStats& ref);

}  // namespace cvtmesh
