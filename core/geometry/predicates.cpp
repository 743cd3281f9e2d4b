#include "core/geometry/predicates.h"

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

double orient2d(const double* a, const double* b, const double* c) {
  return lib().orient2d(p(a), p(b), p(c));
}
double orient3d(const double* a, const double* b, const double* c, const double* d) {
  return -lib().orient3d(p(a), p(b), p(c), p(d));
}
double incircle(const double* a, const double* b, const double* c, const double* d) {
  return lib().incircle(p(a), p(b), p(c), p(d));
}
double insphere(const double* a, const double* b, const double* c, const double* d,
                const double* e) {
  return -lib().insphere(p(a), p(b), p(c), p(d), p(e));
}

}  // namespace cvtmesh
