#include "core/io/write_mesh.h"

#include <gmsh.h>

#include "core/io/format_registry.h"
#include "core/io/gmsh_model.h"
#include "core/io/gmsh_session.h"
#include "core/io/read_mesh.h"
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

void write_with_gmsh(const MeshData& data, const std::string& tmp, const std::string& ext,
                     const WriteOptions& o) {
  GmshSession session;
  std::string previous;
  gmsh::model::getCurrent(previous);
  const auto written = mesh_to_gmsh(data, "cvtmesh_output");
  std::vector<int> views;
  try {
    gmsh_checked("cannot write '" + tmp + "'", [&] {
      gmsh::option::setNumber("Mesh.MshFileVersion", o.msh_version);
      gmsh::option::setNumber("Mesh.Binary", o.binary ? 1 : 0);
      gmsh::option::setNumber("Mesh.SaveAll", 1);
      gmsh::option::setNumber("Mesh.SaveParametric", 0);
      gmsh::write(tmp);
      if (ext == ".msh" && !o.fields.empty()) {
        views = add_element_views(o.fields, written.element_tags);
        gmsh::option::setNumber("PostProcessing.SaveMesh", 0);
        gmsh::option::setNumber("PostProcessing.SaveInterpolationMatrices", 0);
        for (int v : views) gmsh::view::write(v, tmp, true);
      }
    });
  } catch (...) {
    for (int v : views) gmsh::view::remove(v);
    gmsh::model::remove();
    if (!session.owns() && !previous.empty()) gmsh::model::setCurrent(previous);
    throw;
  }
  for (int v : views) gmsh::view::remove(v);
  gmsh::model::remove();
  if (!session.owns() && !previous.empty()) gmsh::model::setCurrent(previous);
}

}  // namespace

std::string supported_write_formats() {
  std::string s = ".msh (4.1 or 2.2)";
  for (const auto& e : own_write_extensions()) s += ", " + e;
  s += ", and Gmsh's .unv .inp .bdf .su2 ...";
  return s;
}

void write_mesh(const MeshData& data, const std::string& path, const WriteOptions& options) {
  const std::string ext = file_extension(path);
  if (ext.empty())
    throw OutputError("cannot write '" + path + "': no file extension to choose the format from");
  const MeshWriter* own = find_writer(ext);
  if (!own && !gmsh_writes(ext))
    throw OutputError("cannot write '" + path + "': unknown output format '" + ext +
                      "' (supported: " + supported_write_formats() + ")");
  if (options.msh_version != 4.1 && options.msh_version != 2.2)
    throw OutputError("unsupported .msh version " + std::to_string(options.msh_version) +
                      " (use 4.1 or 2.2)");
  check_output_allowed(path, options.policy);
  AtomicFile out(path);
  if (own)
    (*own)(data, out.temp_path(), options.fields);
  else
    write_with_gmsh(data, out.temp_path(), ext, options);
  out.commit();
}

}  // namespace cvtmesh
