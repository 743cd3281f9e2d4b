#include "core/geometry/tetgen_library.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <string>

#ifndef CVTMESH_LIBTET_SONAME
#define CVTMESH_LIBTET_SONAME "libtet.so.1.5"
#endif

#if defined(__SANITIZE_ADDRESS__)
#define CVTMESH_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CVTMESH_ASAN 1
#endif
#endif

namespace cvtmesh {
namespace {

// dlopen with RTLD_DEEPBIND. AddressSanitizer's dlopen interceptor refuses RTLD_DEEPBIND (a
// library bound to its own dependencies may call libc's malloc instead of the sanitizer's), so an
// ASan build calls glibc's own dlopen, found in libc.so.6 itself. libtet's direct malloc/free
// calls then stay with libc (TetGen's memory pools: allocated and freed there); its operator new
// and delete go through libstdc++ to the sanitizer's malloc, so arrays TetGen returns in a
// tetgenio and our code deletes look like a malloc/delete[] mismatch to ASan: sanitizer runs set
// ASAN_OPTIONS=alloc_dealloc_mismatch=0 (scripts/sanitize.sh).
void* open_deepbind(const char* name) {
  const int flags = RTLD_NOW | RTLD_LOCAL | RTLD_DEEPBIND;
#ifdef CVTMESH_ASAN
  using Dlopen = void* (*)(const char*, int);
  if (void* libc = dlopen("libc.so.6", RTLD_NOW | RTLD_NOLOAD))
    if (auto real = reinterpret_cast<Dlopen>(dlsym(libc, "dlopen"))) return real(name, flags);
#endif
  return dlopen(name, flags);
}

template <class F>
void bind(void* h, const char* symbol, F& out) {
  void* p = dlsym(h, symbol);
  if (!p)
    throw std::runtime_error(std::string("TetGen library ") + CVTMESH_LIBTET_SONAME + " lacks " +
                             symbol);
  out = reinterpret_cast<F>(p);
}

}  // namespace

const TetgenLibrary& tetgen_library() {
  static TetgenLibrary lib;
  static std::once_flag once;
  std::call_once(once, [] {
    void* h = open_deepbind(CVTMESH_LIBTET_SONAME);
    if (!h)
      throw std::runtime_error(std::string("cannot load TetGen (") + CVTMESH_LIBTET_SONAME + "): " +
                               dlerror() + " - install Debian's libtet1.5 (scripts/setup.sh)");
    TetgenLibrary l;
    bind(h, "_Z14tetrahedralizePcP8tetgenioS1_S1_S1_", l.tetrahedralize);
    bind(h, "_Z8orient2dPdS_S_", l.orient2d);
    bind(h, "_Z8orient3dPdS_S_S_", l.orient3d);
    bind(h, "_Z8incirclePdS_S_S_", l.incircle);
    bind(h, "_Z8inspherePdS_S_S_S_", l.insphere);
    void (*exactinit)(int, int, int, double, double, double) = nullptr;
    bind(h, "_Z9exactinitiiiddd", exactinit);
    // Static filters off (nofilter = 1): the predicates stay exact for coordinates of any size.
    exactinit(0, 0, 1, 1.0, 1.0, 1.0);
    lib = l;
  });
  return lib;
}

}  // namespace cvtmesh
