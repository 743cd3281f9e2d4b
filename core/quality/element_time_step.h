// The explicit time step of one P1 element with lumped mass (wave equation u_tt = c^2 Lap u,
// central differences): dt_e = 2 / (c sqrt(lambda_max(M_e^-1 K_e))), with K_e the element
// stiffness (volume * G G^T, G the #vertices by d gradients of the barycentric functions) and
// M_e = volume / #vertices * I the row-sum lumped mass. The minimum over the elements is the
// per-element bound explicit codes use: by Irons' theorem lambda_max(M_L^-1 K) <= max_e
// lambda_max(M_e^-1 K_e), so min_e dt_e <= the global time step (explicit_time_step.h).
// Pure functions of the coordinates, wave speed c = 1 (the step scales as 1/c).
#pragma once

namespace cvtmesh {

// Tetrahedron a,b,c,d (3 doubles each): 1 / sqrt(lambda_max(sum_i grad phi_i grad phi_i^T)).
// Negative (same magnitude) for a negatively oriented tet, 0 for a flat one.
double tet_time_step(const double* a, const double* b, const double* c, const double* d);
// Triangle a,b,c in the plane (2 doubles each): 2 / sqrt(3 lambda_max(sum_i grad phi_i
// grad phi_i^T)). Negative for a clockwise triangle, 0 for a flat one.
double tri_time_step(const double* a, const double* b, const double* c);

}  // namespace cvtmesh
