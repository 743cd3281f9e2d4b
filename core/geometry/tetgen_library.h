// TetGen 1.5 (Debian's libtet) loaded at run time, isolated from the copy of TetGen that libgmsh
// carries: both export the same C++ symbols (tetgenmesh::*) with different layouts, so linking
// libtet next to libgmsh makes one of them call the other's code and crash. dlopen with
// RTLD_DEEPBIND makes libtet bind to its own symbols; Gmsh keeps its own.
#pragma once

class tetgenio;

namespace cvtmesh {

struct TetgenLibrary {
  void (*tetrahedralize)(char* switches, tetgenio* in, tetgenio* out, tetgenio* addin,
                         tetgenio* bgmin) = nullptr;
  double (*orient2d)(double*, double*, double*) = nullptr;
  double (*orient3d)(double*, double*, double*, double*) = nullptr;
  double (*incircle)(double*, double*, double*, double*) = nullptr;
  double (*insphere)(double*, double*, double*, double*, double*) = nullptr;
};

// Loads libtet once (thread-safe), runs exactinit, and returns its entry points. Throws
// std::runtime_error naming the library if it cannot be loaded.
const TetgenLibrary& tetgen_library();

}  // namespace cvtmesh
