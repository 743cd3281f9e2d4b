#include "core/geometry/predicates.h"

#include <cmath>

#include "core/geometry/tetgen_library.h"

namespace cvtmesh {
namespace {

// Shewchuk's adaptive predicates from TetGen's library (loaded in isolation, see
// tetgen_library.h); exactinit has run once there.
inline double* p(const double* x) {
  return const_cast<double*>(x);
}
inline const TetgenLibrary& lib() {
  static const TetgenLibrary& l = tetgen_library();
  return l;
}

}  // namespace

// Shewchuk's first filters of orient2d and incircle (predicates.c: the same determinants, the
// same error bounds from epsilon = 2^-53): where the rounded determinant's sign is certain it is
// returned here, inline; only the uncertain cases call the library's adaptive evaluation.
constexpr double kEpsilon = 1.1102230246251565404e-16;  // 2^-53
constexpr double kCcwErrBoundA = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr double kIccErrBoundA = (10.0 + 96.0 * kEpsilon) * kEpsilon;

double orient2d(const double* a, const double* b, const double* c) {
  const double detleft = (a[0] - c[0]) * (b[1] - c[1]);
  const double detright = (a[1] - c[1]) * (b[0] - c[0]);
  const double det = detleft - detright;
  double detsum;
  if (detleft > 0) {
    if (detright <= 0) return det;
    detsum = detleft + detright;
  } else if (detleft < 0) {
    if (detright >= 0) return det;
    detsum = -detleft - detright;
  } else {
    return det;
  }
  const double errbound = kCcwErrBoundA * detsum;
  if (det >= errbound || -det >= errbound) return det;
  return lib().orient2d(p(a), p(b), p(c));
}
double orient3d(const double* a, const double* b, const double* c, const double* d) {
  return -lib().orient3d(p(a), p(b), p(c), p(d));
}
double incircle(const double* a, const double* b, const double* c, const double* d) {
  const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
  const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double alift = adx * adx + ady * ady;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double blift = bdx * bdx + bdy * bdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double clift = cdx * cdx + cdy * cdy;
  const double det =
      alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
  const double errbound = kIccErrBoundA * permanent;
  if (det > errbound || -det > errbound) return det;
  return lib().incircle(p(a), p(b), p(c), p(d));
}
double insphere(const double* a, const double* b, const double* c, const double* d,
                const double* e) {
  return -lib().insphere(p(a), p(b), p(c), p(d), p(e));
}

}  // namespace cvtmesh
