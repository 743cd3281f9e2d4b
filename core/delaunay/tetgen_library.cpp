#include "core/delaunay/tetgen_library.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <string>

#ifndef CVTMESH_LIBTET_SONAME
#define CVTMESH_LIBTET_SONAME "libtet.so.1.5"
#endif

namespace cvtmesh {
namespace {

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
    void* h = dlopen(CVTMESH_LIBTET_SONAME, RTLD_NOW | RTLD_LOCAL | RTLD_DEEPBIND);
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
