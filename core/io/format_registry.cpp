#include "core/io/format_registry.h"

#include <map>

namespace cvtmesh {
namespace {

struct Registry {
  std::map<std::string, MeshReader> readers;
  std::map<std::string, MeshWriter> writers;
  Registry() {
    // Formats of our own are registered here as they are implemented (core/io/*_io.h).
  }
};

const Registry& registry() {
  static const Registry r;
  return r;
}

}  // namespace

const MeshReader* find_reader(const std::string& ext) {
  const auto& r = registry().readers;
  auto it = r.find(ext);
  return it == r.end() ? nullptr : &it->second;
}

const MeshWriter* find_writer(const std::string& ext) {
  const auto& w = registry().writers;
  auto it = w.find(ext);
  return it == w.end() ? nullptr : &it->second;
}

std::vector<std::string> own_write_extensions() {
  std::vector<std::string> e;
  for (const auto& [k, v] : registry().writers) e.push_back(k);
  return e;
}

}  // namespace cvtmesh
