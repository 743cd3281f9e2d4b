// Shared by the libFuzzer targets: writes the fuzz input to files in a per-process temporary
// directory (our readers take paths) and runs a reader, accepting only InputError as a refusal.
// Any other exception, a crash or a sanitizer report is a finding.
#pragma once
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "core/util/error.h"

namespace cvtmesh::fuzz {

inline const std::string& temp_dir() {
  static const std::string dir = [] {
    const std::string d =
        (std::filesystem::temp_directory_path() / ("cvtmesh-fuzz-" + std::to_string(getpid())))
            .string();
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

inline std::string write_temp(const std::string& name, std::string_view content) {
  const std::string path = temp_dir() + "/" + name;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(content.data(), content.size());
  return path;
}

template <class F>
void refuse_or_read(F&& read) {
  try {
    read();
  } catch (const InputError&) {
    // A refusal with a message: the expected outcome for bad input.
  }
}

}  // namespace cvtmesh::fuzz
