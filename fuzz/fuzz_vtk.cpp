// libFuzzer target: read_vtk (legacy .vtk) or read_vtu (XML), chosen by the first byte's low bit;
// the rest is the file.
#include <vector>

#include "core/io/vtk_io.h"
#include "fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace cvtmesh;
  if (size == 0) return 0;
  const bool xml = data[0] & 1;
  const std::string_view rest(reinterpret_cast<const char*>(data) + 1, size - 1);
  const std::string path = fuzz::write_temp(xml ? "f.vtu" : "f.vtk", rest);
  std::vector<ElementField> fields;
  fuzz::refuse_or_read([&] { xml ? read_vtu(path, &fields) : read_vtk(path, &fields); });
  return 0;
}
