#include "core/io/read_mesh.h"

#include <gmsh.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/io/format_registry.h"
#include "core/io/gmsh_model.h"
#include "core/io/gmsh_session.h"
#include "core/util/error.h"

namespace cvtmesh {

std::string file_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

namespace {

void check_readable(const std::string& path) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0) throw InputError("cannot read '" + path + "': no such file");
  if (S_ISDIR(st.st_mode)) throw InputError("cannot read '" + path + "': it is a directory");
  if (!S_ISREG(st.st_mode)) throw InputError("cannot read '" + path + "': not a regular file");
  if (access(path.c_str(), R_OK) != 0)
    throw InputError("cannot read '" + path + "': permission denied");
  if (st.st_size == 0) throw InputError("cannot read '" + path + "': the file is empty");
}

// A closed triangulated surface in the current model becomes a volume meshed by Gmsh.
void volume_from_surfaces() {
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::vector<int> tags;
  for (const auto& [d, t] : surfaces) tags.push_back(t);
  const int loop = gmsh::model::geo::addSurfaceLoop(tags);
  gmsh::model::geo::addVolume({loop});
  gmsh::model::geo::synchronize();
  gmsh::model::mesh::generate(3);
}

}  // namespace

MeshData read_mesh(const std::string& path, const ReadOptions& options) {
  check_readable(path);
  const std::string ext = file_extension(path);
  if (const auto* reader = find_reader(ext)) {
    MeshData d = (*reader)(path);
    d.model().source = path;
    return d;
  }
  GmshSession session;
  MeshData data;
  std::string previous;
  gmsh::model::getCurrent(previous);
  gmsh_checked("cannot read '" + path + "'", [&] {
    for (const auto& [name, value] : options.set_numbers) gmsh::onelab::setNumber(name, {value});
    gmsh::option::setNumber("General.NumThreads", 1);
    gmsh::open(path);
  });
  gmsh_checked("cannot mesh '" + path + "'", [&] {
    if (!options.gmsh_optimize) {
      gmsh::option::setNumber("Mesh.Optimize", 0);
      gmsh::option::setNumber("Mesh.OptimizeNetgen", 0);
    }
    if (options.mesh_size_factor > 0)
      gmsh::option::setNumber("Mesh.MeshSizeFactor", options.mesh_size_factor);
    gmsh::option::setNumber("Mesh.RandomSeed", options.seed);
    int model_dim = gmsh::model::getDimension();
    gmsh::vectorpair ents;
    gmsh::model::getEntities(ents);
    if (ents.empty()) throw InputError("'" + path + "' contains no geometry and no mesh");
    // Does the model already carry elements of its dimension?
    auto has_elements = [&](int d) {
      gmsh::vectorpair e;
      gmsh::model::getEntities(e, d);
      for (const auto& [dd, t] : e) {
        std::vector<int> types;
        gmsh::model::mesh::getElementTypes(types, dd, t);
        if (!types.empty()) return true;
      }
      return false;
    };
    const bool is_mesh_file = ext == ".msh" || ext == ".mesh" || ext == ".vtk" || ext == ".unv" ||
                              ext == ".inp" || ext == ".bdf" || ext == ".med";
    const bool is_surface_file = ext == ".stl" || ext == ".off" || ext == ".obj" || ext == ".ply";
    if (is_surface_file && options.dim != 2) {
      volume_from_surfaces();
    } else if (!is_mesh_file) {
      const int want = options.dim > 0 ? options.dim : model_dim;
      if (!has_elements(want)) gmsh::model::mesh::generate(want);
    }
  });
  try {
    data = mesh_from_gmsh(options.dim, "'" + path + "'");
  } catch (...) {
    gmsh::model::remove();
    if (!session.owns()) gmsh::model::setCurrent(previous);
    throw;
  }
  data.model().source = path;
  if (!session.owns()) {
    gmsh::model::remove();
    gmsh::model::setCurrent(previous);
  }
  return data;
}

}  // namespace cvtmesh
