#include "core/io/read_mesh.h"
#include "core/io/read_msh2_periodic.h"
#include "core/io/read_msh_format.h"

#include <optional>

#include "core/io/geo_scan.h"
#include "core/io/process_guard.h"

#include <gmsh.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/geometry/z_range.h"
#include "core/io/finish_mesh.h"
#include "core/io/format_registry.h"
#include "core/io/gmsh_mesh_volumes.h"
#include "core/io/gmsh_surface_mesh3.h"
#include "core/io/gmsh_missing_facets.h"
#include "core/io/gmsh_model.h"
#include "core/io/gmsh_partition_map.h"
#include "core/io/gmsh_repartition.h"
#include "core/io/gmsh_session.h"
#include "core/io/gmsh_surface.h"
#include "core/io/gmsh_views.h"
#include "core/io/surface_io.h"
#include "core/io/write_mesh.h"
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

// A .msh is a sequence of $Section ... $EndSection blocks (also in binary files): a file that does
// not start with a section or does not end with an $End line is garbage or truncated. Gmsh
// itself would try to parse garbage as a script, or read a truncated file up to where it stops.
// A --set/--set-string parameter written into the .geo wrapper: the name an identifier, a string
// value free of what would end its quotes (no code can be injected through it).
void check_geo_parameter(const std::string& path, const std::string& name,
                         const std::string& value) {
  bool ok = !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!ok)
    throw InputError("'" + path + "': parameter name '" + name +
                     "' is not an identifier (letters, digits, _)");
  for (char c : value)
    if (c == '"' || c == '\\' || c == '\n' || c == '\r')
      throw InputError("'" + path + "': the value of string parameter '" + name +
                       "' holds a quote, backslash or line break, which a .geo string cannot "
                       "hold here");
}

void check_msh_frame(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(256, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  const std::size_t first = head.find_first_not_of(" \t\r\n");
  if (first == std::string::npos || head[first] != '$')
    throw InputError("cannot read '" + path +
                     "': not a Gmsh .msh file (it does not start with $MeshFormat)");
  in.clear();
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const std::streamoff n = std::min<std::streamoff>(size, 256);
  std::string tail(static_cast<std::size_t>(n), '\0');
  in.seekg(size - n);
  in.read(tail.data(), n);
  const std::size_t last = tail.find_last_not_of(" \t\r\n");
  const std::size_t line = last == std::string::npos ? 0 : tail.find_last_of('\n', last);
  const std::string end =
      last == std::string::npos ? "" : tail.substr(line == std::string::npos ? 0 : line + 1);
  if (end.rfind("$End", 0) != 0)
    throw InputError("cannot read '" + path +
                     "': the file is truncated (it does not end with an $End... line)");
}

bool is_surface_format(const std::string& ext) {
  return ext == ".stl" || ext == ".off" || ext == ".obj" || ext == ".ply";
}

// Mesh files Gmsh reads (the others it opens are models: .geo, .step, .brep, ...).
bool is_gmsh_mesh_format(const std::string& ext) {
  return ext == ".msh" || ext == ".mesh" || ext == ".vtk" || ext == ".unv" || ext == ".bdf" ||
         ext == ".nas" || ext == ".ply2";
}

// Formats Gmsh 4.8 writes and Debian's cannot read: it would parse them as a .geo script (a
// syntax error on line 1) or, for Diffpack, crash in its reader.
const char* write_only_format(const std::string& ext) {
  static const std::pair<const char*, const char*> kFormats[] = {
      {".inp", "Abaqus"},
      {".su2", "SU2"},
      {".neu", "Gambit neutral"},
      {".wrl", "VRML"},
      {".x3d", "X3D"},
      {".diff", "Diffpack"},
      {".med", "MED (Debian's Gmsh is built without MED)"},
      {".celum", "CELUM"},
      {".tochnog", "Tochnog"}};
  for (const auto& [e, name] : kFormats)
    if (ext == e) return name;
  return nullptr;
}

// A surface file: tetrahedralized by Gmsh (3D), or a planar triangle mesh read as 2D (--dim 2).
MeshData read_surface_file(const std::string& path, const ReadOptions& options) {
  const std::string what = "'" + path + "'";
  if (options.dim != 2) {
    // A closed surface: the volume inside it meshed. An open one not in a plane z = const: a
    // surface mesh in space (gmsh_surface_mesh3.h). An open plane one stays refused (--dim 2
    // reads it as 2D).
    SurfaceMesh s = read_surface(path, false);
    if (surface_closes_up(s)) return tetrahedralize_surface(s, what, options);
    if (z_range(s.xyz).planar) read_surface(path, true);  // throws "not closed"
    return surface_mesh_in_space(s, std::filesystem::path(path).stem().string(), what);
  }
  const SurfaceMesh s = read_surface(path, false);
  MeshData d;
  d.dim = 2;
  const ZRange zr = z_range(s.xyz);
  const double zmin = zr.zmin;
  if (!zr.planar)
    throw InputError(what +
                     ": the surface is not in a plane z = const, so it cannot be read as a "
                     "2D mesh (--dim 2)");
  d.tri.z0 = zmin;
  for (std::size_t v = 0; v < s.xyz.size() / 3; ++v)
    d.tri.xy.insert(d.tri.xy.end(), {s.xyz[3 * v], s.xyz[3 * v + 1]});
  d.tri.tris = s.tris;
  d.tri.model.name = std::filesystem::path(path).stem().string();
  finish_mesh(d, what);
  return d;
}

}  // namespace

bool read_mesh_meshes_a_model(const std::string& path) {
  const std::string ext = file_extension(path);
  return !find_reader(ext) && !is_surface_format(ext) && !is_gmsh_mesh_format(ext);
}

MeshData read_mesh(const std::string& path, const ReadOptions& options) {
  check_readable(path);
  const std::string ext = file_extension(path);
  // An open surface in space that our own reader found (Medit, VTK): Gmsh reads the file below,
  // as a surface mesh in space (gmsh_surface_mesh3.h), its surface references kept as entities.
  bool surface_in_space = false;
  if (const auto* reader = find_reader(ext)) {
    MeshData d;
    try {
      d = (*reader)(path);
    } catch (SurfaceOnlyInput& e) {
      // Triangles in space, no tetrahedra: a closed surface's inside is meshed, as for an .stl.
      if (options.dim == 2) throw;
      surface_in_space = !surface_closes_up(e.surface);
      if (!surface_in_space) {
        orient_shells(e.surface);
        d = tetrahedralize_surface(e.surface, "'" + path + "'", options);
        d.model().read_notes.push_back("'" + path +
                                       "' holds a closed surface and no tetrahedra: the volume "
                                       "inside it meshed by Gmsh, the surface mesh kept");
      }
    }
    if (!surface_in_space) {
      if (options.dim > 0 && d.dim != options.dim)
        throw InputError("'" + path + "' holds a " + std::to_string(d.dim) + "D mesh, not a " +
                         std::to_string(options.dim) + "D one (--dim " +
                         std::to_string(options.dim) + ")");
      d.model().source = path;
      return d;
    }
  }
  if (const char* format = write_only_format(ext))
    throw InputError("cannot read '" + path + "': " + format +
                     " files are written by Gmsh, not read by it or by cvtmesh; convert it to "
                     ".msh first (meshio reads Abaqus .inp, SU2 and MED: meshio convert IN "
                     "OUT.msh)");
  if (is_surface_format(ext)) {
    MeshData d = read_surface_file(path, options);
    d.model().source = path;
    return d;
  }
  if (ext == ".msh") check_msh_frame(path);
  // Parameter names are identifiers and string values cannot close their quotes: the wrapper
  // below writes them into .geo source.
  for (const auto& [name, value] : options.set_numbers) check_geo_parameter(path, name, "");
  for (const auto& [name, value] : options.set_strings) check_geo_parameter(path, name, value);
  const bool script = gmsh_parses_as_script(ext);
  if (script && !options.allow_system_calls) {
    const std::vector<GeoScanFinding> findings = scan_geo_for_processes(path, options.set_strings);
    if (!findings.empty()) throw InputError(geo_scan_message(findings));
  }
  GmshSession session;
  MeshData data;
  std::string previous;
  gmsh::model::getCurrent(previous);
  // Parameters of a .geo are defined before it is parsed (its DefineConstant[] then keeps them),
  // like gmsh -setnumber: through a temporary wrapper that sets them and Includes the model.
  std::string wrapper_dir, wrapper;
  if (ext == ".geo" && (!options.set_numbers.empty() || !options.set_strings.empty())) {
    char tmpl[] = "/tmp/cvtmesh-geo-XXXXXX";
    if (!mkdtemp(tmpl))
      throw InputError("cannot create a temporary directory to set the parameters of '" + path +
                       "'");
    wrapper_dir = tmpl;
    wrapper = wrapper_dir + "/" + std::filesystem::path(path).filename().string();
    std::ofstream w(wrapper);
    for (const auto& [name, value] : options.set_numbers) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.17g", value);
      w << name << " = " << buf << ";\n";
    }
    for (const auto& [name, value] : options.set_strings) w << name << " = \"" << value << "\";\n";
    w << "Include \"" << std::filesystem::absolute(path).string() << "\";\n";
  }
  struct RemoveWrapper {
    std::string dir, file;
    ~RemoveWrapper() {
      if (!file.empty()) std::remove(file.c_str());
      if (!dir.empty()) rmdir(dir.c_str());
    }
  } remove_wrapper{wrapper_dir, wrapper};
  std::vector<int> views_before;
  gmsh::view::getTags(views_before);
  std::string repeated_mesh_note;
  // The views the file brought ($NodeData, $ElementData): read into the mesh, then removed.
  auto new_views = [&] {
    std::vector<int> views, fresh;
    gmsh::view::getTags(views);
    for (int v : views)
      if (std::find(views_before.begin(), views_before.end(), v) == views_before.end())
        fresh.push_back(v);
    return fresh;
  };
  gmsh_checked("cannot read '" + path + "'", [&] {
    gmsh::option::setNumber("General.NumThreads", 1);
    std::vector<std::string> log_before, log;
    gmsh::logger::get(log_before);
    {
      // Whatever the scan did not see cannot start a process either (process_guard.h).
      std::optional<ProcessGuard> guard;
      if (!options.allow_system_calls) guard.emplace();
      gmsh::open(wrapper.empty() ? path : wrapper);
      if (guard && !guard->refused().empty())
        throw InputError("'" + path + "': Gmsh was asked to run '" + guard->refused().front() +
                         "'; refused: cvtmesh does not run programs from model files unless given "
                         "--allow-system-calls (docs/reliability.md, Security)");
    }
    // Gmsh keeps the first of two nodes or elements with one tag and only logs it: ambiguous
    // data, refused (the log holds messages only when our session started the logger).
    // A file that repeats its mesh identically (a view appended with the mesh written again)
    // is read once, with a note.
    gmsh::logger::get(log);
    bool repeats_checked = false;
    for (std::size_t i = std::min(log_before.size(), log.size()); i < log.size(); ++i)
      for (const char* dup : {"Skipping duplicate node", "Skipping duplicate element"})
        if (const auto at = log[i].find(dup); at != std::string::npos && !repeats_checked) {
          if (!msh_repeats_identical_sections(path))
            throw InputError("'" + path + "': tags are not unique (Gmsh: " + log[i].substr(at) +
                             ")");
          repeats_checked = true;
          repeated_mesh_note = "'" + path +
                               "' holds its mesh more than once, every copy the same (a view "
                               "appended with the mesh): read once";
        }
  });
  ElementOrigin origin = ElementOrigin::kModel;
  std::vector<std::string> read_notes;
  if (!repeated_mesh_note.empty()) read_notes.push_back(repeated_mesh_note);
  std::vector<std::array<int, 3>> file_blocks;
  try {
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
      if (!is_gmsh_mesh_format(ext)) {
        const int want = options.dim > 0 ? options.dim : model_dim;
        if (!has_elements(want)) gmsh::model::mesh::generate(want);
      } else {
        // The blocks the file holds: a .msh writer writes these and no others (write_mesh.h).
        origin = ElementOrigin::kMeshFile;
        // A partitioned file's blocks are its model entities' (gmsh_partition_map.h); one file
        // of a mesh saved one file per part is refused.
        const GmshPartitionMap parts = read_gmsh_partition_map(
            "'" + path + "'", ext == ".msh" ? read_msh_partition_count(path) : 0);
        for (const auto& [d, t] : ents) {
          const GmshDimTag owner = parts.element_owner(d, t);
          if (owner.first < 0) continue;
          std::vector<int> types;
          gmsh::model::mesh::getElementTypes(types, d, t);
          for (int type : types) file_blocks.push_back({owner.first, owner.second, type});
        }
        std::sort(file_blocks.begin(), file_blocks.end());
        file_blocks.erase(std::unique(file_blocks.begin(), file_blocks.end()), file_blocks.end());
        // A surface mesh of volumes without tetrahedra (gmsh -2 -save_all, a closed surface in a
        // mesh format): the volumes are meshed, the file's blocks written back with them.
        if (options.dim != 2 && is_surface_mesh_of_volumes()) {
          // Gmsh meshes a volume from its model surfaces' elements, which a partitioned file
          // holds on partition entities (their curves' and points' nodes moved too).
          if (parts.partitioned())
            throw InputError("'" + path + "' is a partitioned surface mesh of volumes without " +
                             "tetrahedra: cvtmesh does not mesh the volumes of a partitioned " +
                             "surface mesh; save it unpartitioned (without -part), or mesh the " +
                             "volumes first (gmsh -3 -part N)");
          // Surfaces Gmsh cannot mesh the inside of (they bound no volume: overlapping or
          // crossing sheets, quadrangles) are read as they are, a surface mesh in space
          // (gmsh_surface_mesh3.h), from the file opened again.
          std::vector<int> volumes;
          std::string refused;
          try {
            volumes = mesh_volumes_of_surface_mesh("'" + path + "'", options);
          } catch (const InputError& e) {
            refused = e.what();
          } catch (...) {
            // Gmsh's own failure: its last logged error says what.
            std::string last;
            try {
              gmsh::logger::getLastError(last);
            } catch (...) {
            }
            refused = last.empty() ? std::string("Gmsh failed") : last;
          }
          if (refused.empty()) {
            for (int v : volumes) file_blocks.push_back({3, v, 4});
            std::sort(file_blocks.begin(), file_blocks.end());
            read_notes.push_back("'" + path + "' holds surfaces and no tetrahedra: " +
                                 std::to_string(volumes.size()) +
                                 " volume(s) inside them meshed by Gmsh, the surface mesh kept");
          } else {
            std::string name;
            gmsh::model::getCurrent(name);
            gmsh::model::remove();
            gmsh::model::add(name);
            gmsh::merge(path);
            read_notes.push_back("'" + path + "': the volumes inside its surfaces cannot be " +
                                 "meshed (" + refused + "): read as a surface mesh");
          }
        }
        // A .msh saved with physical groups may lack the boundary elements of other surfaces.
        int want = options.dim;
        if (want < 0) want = has_elements(3) ? 3 : 2;
        // Not for a surface mesh in space: its open borders need no line elements (the file's
        // are kept as they are; a compound curve of t12 would get one line more).
        if (!(options.dim < 0 && want == 2 && gmsh_surface_mesh_in_space()))
          add_missing_facets(want);
      }
    });
    data = mesh_from_gmsh(options.dim, "'" + path + "'");
    const std::vector<int> fresh = new_views();
    if (!fresh.empty()) {
      gmsh_checked("cannot read the views of '" + path + "'", [&] {
        data.model().views = read_gmsh_views(fresh, data, "'" + path + "'", read_notes);
      });
      for (int v : fresh) gmsh::view::remove(v);
    }
  } catch (...) {
    for (int v : new_views()) gmsh::view::remove(v);
    gmsh::model::remove();
    if (!session.owns()) gmsh::model::setCurrent(previous);
    throw;
  }
  data.model().source = path;
  // Gmsh 4.8 does not give back the $Periodic section of an MSH 2.2 file.
  if (ext == ".msh" && data.model().periodic.empty() && read_msh_format(path).version < 3)
    data.model().periodic = read_msh2_periodic(path);
  data.model().origin = origin;
  data.model().read_notes.insert(data.model().read_notes.end(), read_notes.begin(),
                                 read_notes.end());
  // An order-2 file's blocks are written back as order 2 from their linear counterparts.
  if (data.model().high_order.order == 2) {
    for (auto& b : file_blocks) b[2] = b[2] == 8 ? 1 : b[2] == 9 ? 2 : b[2] == 11 ? 4 : b[2];
    std::sort(file_blocks.begin(), file_blocks.end());
  }
  data.model().file_blocks = std::move(file_blocks);
  // A partitioned .msh: how a writer tells that the mesh reaches it unchanged (gmsh_repartition.h).
  if (Partitioning& parts = data.model().partitioning; parts.nb_parts > 0 && ext == ".msh") {
    parts.mesh_fingerprint = partition_fingerprint(data);
    parts.source_stamp = file_stamp(path);
  }
  // The placeholder group of our MSH 2.2 output (see write_mesh.h) is not a user's group.
  auto& groups = data.model().groups;
  groups.erase(std::remove_if(groups.begin(), groups.end(),
                              [](const PhysicalGroup& g) { return g.name == kUnassignedGroup; }),
               groups.end());
  if (!session.owns()) {
    gmsh::model::remove();
    gmsh::model::setCurrent(previous);
  }
  return data;
}

}  // namespace cvtmesh
