// libFuzzer target: read_tetgen on X.node + X.ele [+ X.face]. The input holds the files one after
// the other, separated by lines "@@" (.node, .ele, then an optional .face).
#include "core/io/tetgen_io.h"
#include "fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace cvtmesh;
  const std::string_view in(reinterpret_cast<const char*>(data), size);
  std::string_view parts[3];
  std::size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const std::size_t at = i < 2 ? in.find("\n@@\n", start) : std::string_view::npos;
    parts[i] = in.substr(start, at == std::string_view::npos ? in.size() - start : at - start);
    if (at == std::string_view::npos) {
      start = in.size();
      for (int j = i + 1; j < 3; ++j) parts[j] = {};
      break;
    }
    start = at + 4;
  }
  std::filesystem::remove(fuzz::temp_dir() + "/f.face");
  const std::string node = fuzz::write_temp("f.node", parts[0]);
  fuzz::write_temp("f.ele", parts[1]);
  if (!parts[2].empty()) fuzz::write_temp("f.face", parts[2]);
  fuzz::refuse_or_read([&] { read_tetgen(node); });
  return 0;
}
