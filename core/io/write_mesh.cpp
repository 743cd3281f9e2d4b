#include "core/io/write_mesh.h"

#include "core/io/append_msh_periodic.h"

#include <gmsh.h>

#include <algorithm>
#include <initializer_list>
#include <map>
#include <vector>

#include "core/io/format_registry.h"
#include "core/io/gmsh_model.h"
#include "core/io/gmsh_session.h"
#include "core/io/read_mesh.h"
#include "core/io/tetgen_io.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

// Formats Gmsh writes from a mesh (besides .msh).
bool gmsh_writes(const std::string& ext) {
  static const char* k[] = {".msh",  ".unv", ".inp", ".bdf", ".p3d",   ".diff", ".ir3",
                            ".mail", ".su2", ".wrl", ".x3d", ".celum", ".off"};
  for (const char* e : k)
    if (ext == e) return true;
  return false;
}

// MSH 2.2 stores physical groups only through the elements' physical tags, and Gmsh writes the
// tags only when it saves the elements of physical groups alone (Mesh.SaveAll = 0). To keep both
// the groups and every element, entities outside every group of their dimension are put in a
// group named kUnassignedGroup, which read_mesh drops again.
void keep_groups_in_msh22() {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  if (groups.empty()) {
    gmsh::option::setNumber("Mesh.SaveAll", 1);
    return;
  }
  std::map<int, std::vector<int>> uncovered;
  std::map<int, int> max_tag;
  for (const auto& [d, t] : groups) max_tag[d] = std::max(max_tag[d], t);
  gmsh::vectorpair ents;
  gmsh::model::getEntities(ents);
  for (const auto& [d, t] : ents) {
    std::vector<int> types, phys;
    gmsh::model::mesh::getElementTypes(types, d, t);
    if (types.empty()) continue;
    gmsh::model::getPhysicalGroupsForEntity(d, t, phys);
    if (phys.empty()) uncovered[d].push_back(t);
  }
  for (const auto& [d, tags] : uncovered) {
    const int tag = gmsh::model::addPhysicalGroup(d, tags, max_tag[d] + 1);
    gmsh::model::setPhysicalName(d, tag, kUnassignedGroup);
  }
  gmsh::option::setNumber("Mesh.SaveAll", 0);
}

void write_with_gmsh(const MeshData& data, const std::string& tmp, const std::string& target,
                     const std::string& ext, const WriteOptions& o) {
  GmshSession session;
  std::string previous;
  gmsh::model::getCurrent(previous);
  std::vector<int> views;
  bool made = false;
  auto cleanup = [&] {
    for (int v : views) gmsh::view::remove(v);
    if (made) gmsh::model::remove();
    if (!session.owns() && !previous.empty()) gmsh::model::setCurrent(previous);
  };
  try {
    const auto written = mesh_to_gmsh(data, "cvtmesh_output");
    made = true;
    gmsh_checked("cannot write '" + target + "'", [&] {
      gmsh::option::setNumber("Mesh.MshFileVersion", o.msh_version);
      gmsh::option::setNumber("Mesh.Binary", o.binary ? 1 : 0);
      gmsh::option::setNumber("Mesh.SaveAll", 1);
      gmsh::option::setNumber("Mesh.SaveParametric", 0);
      if (ext == ".msh" && o.msh_version < 3) keep_groups_in_msh22();
      gmsh::write(tmp);
      if (ext == ".msh") append_msh_periodic(tmp, data.model().periodic, o.msh_version, o.binary);
      if (ext == ".msh" && !o.fields.empty()) {
        views = add_element_views(o.fields, written.element_tags);
        gmsh::option::setNumber("PostProcessing.SaveMesh", 0);
        gmsh::option::setNumber("PostProcessing.SaveInterpolationMatrices", 0);
        for (int v : views) gmsh::view::write(v, tmp, true);
      }
    });
  } catch (const InputError& e) {
    cleanup();
    throw OutputError(e.what());
  } catch (...) {
    cleanup();
    throw;
  }
  cleanup();
}

// Runs a writer on temporaries; its errors name the temporary it was given: they are rethrown
// naming the file the user asked for.
template <class F>
void name_targets(std::initializer_list<const AtomicFile*> files, F&& write) {
  try {
    write();
  } catch (const OutputError& e) {
    std::string message = e.what();
    for (const AtomicFile* f : files)
      for (std::size_t at; (at = message.find(f->temp_path())) != std::string::npos;)
        message.replace(at, f->temp_path().size(), f->target());
    throw OutputError(message);
  }
}

bool is_tetgen(const std::string& ext) {
  return ext == ".node" || ext == ".ele";
}

// Formats that store per-element fields: .msh ($ElementData), VTK (cell data), TetGen (.ele
// attributes).
bool holds_fields(const std::string& ext) {
  return ext == ".msh" || ext == ".vtk" || ext == ".vtu" || is_tetgen(ext);
}

// TetGen/Triangle: X.node, X.ele and X.face (X.edge in 2D) are written to temporaries and only
// renamed when all three are complete.
void write_tetgen_files(const MeshData& data, const std::string& path, const WriteOptions& o) {
  const TetgenFiles files = tetgen_files(path, data.dim);
  for (const std::string* f : {&files.node, &files.ele, &files.facets})
    check_output_allowed(*f, o.policy);
  AtomicFile node(files.node), ele(files.ele), facets(files.facets);
  name_targets({&node, &ele, &facets}, [&] {
    write_tetgen(data, {node.temp_path(), ele.temp_path(), facets.temp_path()}, o.fields);
  });
  node.commit();
  ele.commit();
  facets.commit();
}

}  // namespace

std::string supported_write_formats() {
  std::string s = ".msh (4.1 or 2.2), .node (TetGen .node/.ele/.face)";
  for (const auto& e : own_write_extensions()) s += ", " + e;
  s += ", and Gmsh's .unv .inp .bdf .su2 ...";
  return s;
}

void check_can_write(const std::string& path, const WriteOptions& options) {
  const std::string ext = file_extension(path);
  if (ext.empty())
    throw OutputError("cannot write '" + path + "': no file extension to choose the format from");
  if (!find_writer(ext) && !gmsh_writes(ext) && !is_tetgen(ext))
    throw OutputError("cannot write '" + path + "': unknown output format '" + ext +
                      "' (supported: " + supported_write_formats() + ")");
  if (!options.fields.empty() && !holds_fields(ext))
    throw OutputError("cannot write '" + path + "': the " + ext +
                      " format cannot hold per-element data (--quality); use .msh, .vtk, .vtu or "
                      ".node");
  if (options.msh_version != 4.1 && options.msh_version != 2.2)
    throw OutputError("unsupported .msh version " + std::to_string(options.msh_version) +
                      " (use 4.1 or 2.2)");
  if (is_tetgen(ext)) {
    // .node and .ele here; the facet file (.face or .edge, by dimension) when writing.
    const TetgenFiles files = tetgen_files(path, 3);
    for (const std::string* f : {&files.node, &files.ele}) check_output_allowed(*f, options.policy);
  } else {
    check_output_allowed(path, options.policy);
  }
  check_directory_writable(path);
}

void write_mesh(const MeshData& data, const std::string& path, const WriteOptions& options) {
  if (data.dim != 2 && data.dim != 3)
    throw InvariantError("write_mesh: MeshData.dim must be 2 or 3");
  check_can_write(path, options);
  const std::string ext = file_extension(path);
  const MeshWriter* own = find_writer(ext);
  if (is_tetgen(ext)) {
    write_tetgen_files(data, path, options);
    return;
  }
  AtomicFile out(path);
  name_targets({&out}, [&] {
    if (own)
      (*own)(data, out.temp_path(), options.fields);
    else
      write_with_gmsh(data, out.temp_path(), path, ext, options);
  });
  out.commit();
}

}  // namespace cvtmesh
