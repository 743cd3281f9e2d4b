#include "core/io/format_registry.h"

#include <map>

#include "core/io/medit_io.h"
#include "core/io/surface_io.h"
#include "core/io/tetgen_io.h"
#include "core/io/vtk_io.h"

namespace cvtmesh {
namespace {

struct Registry {
  std::map<std::string, MeshReader> readers;
  std::map<std::string, MeshWriter> writers;
  Registry() {
    // Formats of our own (core/io/*_io.h). TetGen's .node/.ele/.face is several files: its
    // writer is called by write_mesh itself; surfaces are read by read_mesh (they need meshing).
    readers[".vtk"] = [](const std::string& p) { return read_vtk(p); };
    readers[".vtu"] = [](const std::string& p) { return read_vtu(p); };
    readers[".node"] = read_tetgen;
    readers[".ele"] = read_tetgen;
    readers[".mesh"] = read_medit;
    writers[".vtk"] = write_vtk;
    writers[".vtu"] = write_vtu;
    // Medit has no element data in the .mesh itself: fields are not written.
    writers[".mesh"] = [](const MeshData& d, const std::string& p,
                          const std::vector<ElementField>&) { write_medit(d, p); };
    for (const char* e : {".off", ".obj", ".ply", ".stl"})
      writers[e] = [](const MeshData& d, const std::string& p, const std::vector<ElementField>&) {
        write_surface(d, p);
      };
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
