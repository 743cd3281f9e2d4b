// Exact/adaptive geometric predicates (Shewchuk's, as exported by TetGen's libtet).
// Signs are normalised to our orientation convention:
//   orient2d(a,b,c) > 0  iff a,b,c are counter-clockwise;
//   orient3d(a,b,c,d) > 0 iff the signed volume (b-a).((c-a)x(d-a))/6 is positive;
//   incircle(a,b,c,d) > 0 iff d is strictly inside the circle of counter-clockwise a,b,c;
//   insphere(a,b,c,d,e) > 0 iff e is strictly inside the sphere of positively oriented a,b,c,d.
// The magnitude is only an approximation of the determinant; the sign is exact.
#pragma once

namespace cvtmesh {

double orient2d(const double* a, const double* b, const double* c);
double orient3d(const double* a, const double* b, const double* c, const double* d);
double incircle(const double* a, const double* b, const double* c, const double* d);
double insphere(const double* a, const double* b, const double* c, const double* d,
                const double* e);

}  // namespace cvtmesh
