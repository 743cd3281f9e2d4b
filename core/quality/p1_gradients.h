// The gradients of the P1 (barycentric) basis functions of a tetrahedron, scaled: for tet a,b,c,d
// (3 doubles each) n[i] = det * grad phi_i, i = 0..3 in the order a,b,c,d, with det = 6 * signed
// volume (returned). n[1..3] are the cross products of the edge vectors from a (the rows of
// det * [b-a c-a d-a]^-1), n[0] minus their sum. Shared by the FE measures (p1_system,
// vertex_time_step).
#pragma once

namespace cvtmesh {

double tet_scaled_gradients(const double* a, const double* b, const double* c, const double* d,
                            double n[4][3]);

}  // namespace cvtmesh
