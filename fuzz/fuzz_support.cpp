// What the readers need from the parts of core/ the fuzz build leaves out (they need libgmsh):
// file_extension (core/io/read_mesh.cpp) and the TetGen predicates, here from libtet linked
// directly - without libgmsh in the process there is no symbol clash, so no dlopen(RTLD_DEEPBIND)
// (which AddressSanitizer refuses) is needed.
#include <tetgen.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <mutex>
#include <string>

#include "core/geometry/tetgen_library.h"
#include "core/io/read_mesh.h"

// Exported by libtet (Shewchuk's predicates.cxx) but not declared in tetgen.h.
REAL orient2d(REAL* pa, REAL* pb, REAL* pc);
REAL incircle(REAL* pa, REAL* pb, REAL* pc, REAL* pd);

namespace cvtmesh {

std::string file_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

const TetgenLibrary& tetgen_library() {
  static TetgenLibrary lib;
  static std::once_flag once;
  std::call_once(once, [] {
    lib.tetrahedralize =
        static_cast<void (*)(char*, tetgenio*, tetgenio*, tetgenio*, tetgenio*)>(&::tetrahedralize);
    lib.orient2d = &::orient2d;
    lib.orient3d = &::orient3d;
    lib.incircle = &::incircle;
    lib.insphere = &::insphere;
    ::exactinit(0, 0, 1, 1.0, 1.0, 1.0);  // as core/geometry/tetgen_library.cpp
  });
  return lib;
}

}  // namespace cvtmesh
