// libFuzzer target: read_mesh on the input as a .msh file — our frame pre-check
// (core/io/read_mesh.cpp), Gmsh's parser (libgmsh, in the process, not instrumented), then our
// conversion of Gmsh's model (core/io/gmsh_model.cpp) and the checks of finish_mesh. A crash
// anywhere, a sanitizer report in our code, or an exception other than InputError is a finding.
#include "core/io/read_mesh.h"
#include "fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace cvtmesh;
  const std::string path =
      fuzz::write_temp("f.msh", std::string_view(reinterpret_cast<const char*>(data), size));
  fuzz::refuse_or_read([&] { read_mesh(path); });
  return 0;
}
