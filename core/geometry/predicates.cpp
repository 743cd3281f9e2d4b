#include "core/geometry/predicates.h"

#include <mutex>

// Shewchuk's robust predicates, compiled into TetGen's libtet (tetgen.h declares only some).
double orient2d(double* pa, double* pb, double* pc);
double orient3d(double* pa, double* pb, double* pc, double* pd);
double incircle(double* pa, double* pb, double* pc, double* pd);
double insphere(double* pa, double* pb, double* pc, double* pd, double* pe);
void exactinit(int verbose, int noexact, int nofilter, double maxx, double maxy, double maxz);

namespace cvtmesh {
namespace {

// exactinit() computes the machine epsilon and splitter used by the adaptive stages. It must run
// once before any predicate; static-filter bounds are disabled (nofilter=1) so that the
// predicates are valid for coordinates of any magnitude.
void ensure_init() {
  static std::once_flag once;
  std::call_once(once, [] { exactinit(0, 0, 1, 1.0, 1.0, 1.0); });
}
inline double* p(const double* x) { return const_cast<double*>(x); }

}  // namespace

double orient2d(const double* a, const double* b, const double* c) {
  ensure_init();
  return ::orient2d(p(a), p(b), p(c));
}
double orient3d(const double* a, const double* b, const double* c, const double* d) {
  ensure_init();
  return -::orient3d(p(a), p(b), p(c), p(d));
}
double incircle(const double* a, const double* b, const double* c, const double* d) {
  ensure_init();
  return ::incircle(p(a), p(b), p(c), p(d));
}
double insphere(const double* a, const double* b, const double* c, const double* d,
                const double* e) {
  ensure_init();
  return -::insphere(p(a), p(b), p(c), p(d), p(e));
}

}  // namespace cvtmesh
