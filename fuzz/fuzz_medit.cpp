// libFuzzer target: read_medit on the input as a .mesh file.
#include "core/io/medit_io.h"
#include "fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace cvtmesh;
  const std::string path =
      fuzz::write_temp("f.mesh", std::string_view(reinterpret_cast<const char*>(data), size));
  fuzz::refuse_or_read([&] { read_medit(path); });
  return 0;
}
