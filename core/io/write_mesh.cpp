#include "core/io/write_mesh.h"

#include "core/io/add_curve_point_elements.h"
#include "core/io/append_msh_periodic.h"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <vector>

#include "core/io/format_registry.h"
#include "core/io/gmsh_model.h"
#include "core/io/gmsh_repartition.h"
#include "core/io/gmsh_views.h"
#include "core/io/gmsh_session.h"
#include "core/io/quality_view_geo.h"
#include "core/io/read_mesh.h"
#include "core/io/read_msh_format.h"
#include "core/io/select_msh_elements.h"
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

// The views of data's model that belong to its mesh as it is (DataView::fingerprint).
std::vector<DataView> views_of(const MeshData& data) {
  std::vector<DataView> out;
  if (data.model().views.empty()) return out;
  const std::uint64_t f = mesh_fingerprint(data);
  for (const DataView& v : data.model().views)
    if (v.fingerprint == f) out.push_back(v);
  return out;
}

// A partitioned .msh input that reaches the writer as it was read, its file unchanged too.
bool unchanged_partitioned_input(const MeshData& data) {
  const Partitioning& p = data.model().partitioning;
  return p.nb_parts > 0 && !p.source_stamp.empty() &&
         file_stamp(data.model().source) == p.source_stamp &&
         partition_fingerprint(data) == p.mesh_fingerprint;
}

// Whether Gmsh reads the file it wrote (into a scratch model, removed again).
bool gmsh_reads_back(const std::string& path) {
  std::string current;
  gmsh::model::getCurrent(current);
  gmsh::model::add("cvtmesh_read_back");
  bool ok = true;
  try {
    gmsh_checked("read back", [&] { gmsh::merge(path); });
  } catch (const InputError&) {
    ok = false;
  }
  gmsh::model::remove();
  gmsh::model::setCurrent(current);
  return ok;
}

Repartitioned write_with_gmsh(const MeshData& data, const std::string& tmp,
                              const std::string& target, const std::string& ext,
                              const WriteOptions& o) {
  Repartitioned parted;
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
    // A .msh holds what Gmsh would save of this model (select_msh_elements.h); per-element data
    // covers every written element, numbered in file order, as meshio reads it (a partitioned
    // output: the cells, by their tags).
    const bool msh = ext == ".msh";
    const bool partitioned = msh && data.model().partitioning.nb_parts > 0;
    MshSelection selection;
    bool save_all = true;
    std::vector<ElementField> fields;
    std::vector<std::size_t> field_tags;
    // The input's views (not on a partitioned output: its parts order the file, the note says).
    const std::vector<DataView> data_views =
        msh && !partitioned ? views_of(data) : std::vector<DataView>{};
    std::size_t nb_elements = 0;  // with views: every element tagged 1..N in file order
    if (msh) {
      selection = select_msh_elements(data, o.save_all);
      save_all = selection.save_all;
      if (o.msh_version < 3 && selection.outside_groups)
        throw OutputError("cannot write '" + target +
                          "' as MSH 2.2: some of its elements are in no physical group, and MSH "
                          "2.2 stores groups only as the tags of elements that have one; write "
                          "MSH 4.1 (--msh-version 4.1) or put those entities in a physical group");
      // Per-node and per-element data are read back by position (meshio) as by tag (Gmsh).
      if (!data_views.empty()) {
        nb_elements = number_in_file_order(selection.data);
        number_nodes_in_file_order(selection.data);
      }
      if (!o.fields.empty() && !partitioned) {
        const std::size_t n = number_in_file_order(selection.data);
        fields = fields_on_all_elements(selection, o.fields, n);
        for (std::size_t t = 1; t <= n; ++t) field_tags.push_back(t);
      }
    }
    // A partitioned input: Gmsh partitions the whole mesh (its facets keep the nodes on their
    // entities: Gmsh moves a node of an entity without elements into a part) and saves what the
    // selection holds (Mesh.SaveAll as for the selection: the physical groups' elements, which
    // the partition entities inherit).
    // A partitioned input whose mesh is unchanged (cvtmesh convert): its file merged and
    // written again, its own parts kept (METIS would not cut this mesh as the input's file had
    // it: the graph holds the elements Gmsh had in memory).
    const bool keep_file = partitioned && unchanged_partitioned_input(data);
    MeshData full;
    if (partitioned && !keep_file) {
      full = data;
      add_curve_point_elements(full);
    }
    GmshWritten written;
    if (keep_file) {
      gmsh_checked("cannot read '" + data.model().source + "' again", [&] {
        gmsh::model::add("cvtmesh_output");
        made = true;
        gmsh::merge(data.model().source);
      });
      parted.nb_parts = data.model().partitioning.nb_parts;
      parted.same_as_input = parted.kept_input_file = true;
      // The cells' tags are the file's.
      const auto& tags = data.dim == 3 ? data.tet.tet_tags : data.tri.tri_tags;
      const int npe = data.dim + 1;
      const auto& cells = data.dim == 3 ? data.tet.tets : data.tri.tris;
      for (std::size_t c = 0; c < tags.size(); ++c)
        if (cells[npe * c] >= 0) written.element_tags.push_back(tags[c]);
    } else {
      written = mesh_to_gmsh(partitioned ? full : msh ? selection.data : data, "cvtmesh_output");
      made = true;
      if (partitioned) parted = repartition_gmsh_model(data.model().partitioning, data.dim);
    }
    // The views' cells: element tags per live simplex of `data` (the selection's cells map back
    // to them by field_index).
    std::vector<std::size_t> cell_tags;
    if (!data_views.empty()) {
      cell_tags.assign(nb_live_cells(data), 0);
      const std::vector<int>& cells =
          data.dim == 3 ? selection.data.tet.tets : selection.data.tri.tris;
      const std::size_t npe = data.dim + 1;
      std::size_t k = 0;
      for (std::size_t c = 0; c * npe < cells.size(); ++c) {
        if (cells[npe * c] < 0) continue;
        const long i = c < selection.field_index.size() ? selection.field_index[c] : -1;
        if (i >= 0 && static_cast<std::size_t>(i) < cell_tags.size() &&
            k < written.element_tags.size())
          cell_tags[i] = written.element_tags[k];
        ++k;
      }
    }
    if (partitioned) {
      // The fields on the written cells, by their tags (the file's order is the parts').
      for (const ElementField& f : o.fields) {
        ElementField g{f.name, {}};
        field_tags.clear();
        for (long i : selection.field_index)
          if (i >= 0 && static_cast<std::size_t>(i) < written.element_tags.size() &&
              static_cast<std::size_t>(i) < f.values.size()) {
            field_tags.push_back(written.element_tags[i]);
            g.values.push_back(f.values[i]);
          }
        fields.push_back(std::move(g));
      }
    }
    gmsh_checked("cannot write '" + target + "'", [&] {
      gmsh::option::setNumber("Mesh.MshFileVersion", o.msh_version);
      gmsh::option::setNumber("Mesh.Binary", o.binary ? 1 : 0);
      gmsh::option::setNumber("Mesh.SaveAll", save_all ? 1 : 0);
      gmsh::option::setNumber("Mesh.SaveParametric", 0);
      gmsh::write(tmp);
      if (partitioned && o.msh_version < 3 && !gmsh_reads_back(tmp)) {
        // Gmsh 4.8 rebuilds the parts of an MSH 2.2 file (its partition tags) when it reads it
        // and fails on some ("No mesh elements were found"): such a file is written unpartitioned
        // (MSH 2.2 holds no node classification that the unpartitioned mesh would lose).
        gmsh::model::mesh::unpartition();
        gmsh::write(tmp);
        parted = Repartitioned{};
        parted.unreadable_msh22 = true;
      }
      // Gmsh writes the periodic links of a merged MSH 4 file itself (not an MSH 2.2 one's).
      const bool own_periodic = keep_file && read_msh_format(data.model().source).version >= 3;
      if (msh && !own_periodic)
        append_msh_periodic(tmp, data.model().periodic, o.msh_version, o.binary);
      if (msh && (!fields.empty() || !data_views.empty())) {
        // Quality fields first (the .opt shows View[0]), then the input's views.
        if (!fields.empty()) views = add_element_views(fields, field_tags);
        for (int v : add_data_views(data_views, written.node_tags, cell_tags, nb_elements))
          views.push_back(v);
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
  return parted;
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

// Formats that store per-element fields: .msh ($ElementData), VTK (cell data). Not TetGen's
// .ele: its attributes are real numbers for TetGen, but meshio reads them as integers and fails.
bool holds_fields(const std::string& ext) {
  return ext == ".msh" || ext == ".vtk" || ext == ".vtu";
}

constexpr const char* kOptMarker = "// Written by cvtmesh";

// PATH.opt, merged by Gmsh when it opens PATH: the first field's view alone, over its range, and
// for a volume mesh cut through its centre by the plane that faces the camera (camera_cut.h).
std::string quality_opt(const MeshData& data, const std::string& path,
                        const std::vector<ElementField>& fields) {
  double lo = 0, hi = 0;
  finite_range(fields.front(), lo, hi);
  char range[128];
  std::snprintf(range, sizeof range, "%.6g, %.6g", lo, hi);
  return std::string(kOptMarker) + " with " + path +
         "; Gmsh merges it when it opens that file.\n// The view \"" + fields.front().name +
         "\" alone, coloured over the range of its values [" + range + "].\n" +
         "View[0].Visible = 1;\nView[0].SaturateValues = 1;\n" +
         quality_view_geo(data, fields, "0");
}

bool is_our_opt(const std::string& opt) {
  std::ifstream in(opt);
  std::string first;
  return in && std::getline(in, first) && first.rfind(kOptMarker, 0) == 0;
}

// Writes PATH.opt with fields, or removes a stale one of ours without; a user's own is kept.
void write_companion_opt(const MeshData& data, const std::string& path, const WriteOptions& o) {
  const std::string opt = path + ".opt";
  std::error_code ec;
  const bool exists = std::filesystem::exists(opt, ec);
  if (exists && !is_our_opt(opt)) return;
  if (o.fields.empty()) {
    if (exists) std::filesystem::remove(opt, ec);
    return;
  }
  AtomicFile out(opt);
  {
    std::ofstream f(out.temp_path());
    f << quality_opt(data, std::filesystem::path(path).filename().string(), o.fields);
    if (!f.flush()) throw OutputError("cannot write '" + opt + "'");
  }
  out.commit();
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
    throw OutputError("cannot write '" + path + "': the " + ext + " format " +
                      (is_tetgen(ext) ? "holds per-element data only as attributes that meshio "
                                        "reads as integers"
                                      : "cannot hold per-element data") +
                      " (--quality); use .msh, .vtk or .vtu");
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

WriteReport write_mesh(const MeshData& data, const std::string& path, const WriteOptions& options) {
  WriteReport report;
  if (data.dim != 2 && data.dim != 3)
    throw InvariantError("write_mesh: MeshData.dim must be 2 or 3");
  check_can_write(path, options);
  const std::string ext = file_extension(path);
  const MeshWriter* own = find_writer(ext);
  const Partitioning& parts = data.model().partitioning;
  Repartitioned parted;
  if (is_tetgen(ext)) {
    write_tetgen_files(data, path, options);
  } else {
    AtomicFile out(path);
    name_targets({&out}, [&] {
      if (own)
        (*own)(data, out.temp_path(), options.fields);
      else
        parted = write_with_gmsh(data, out.temp_path(), path, ext, options);
    });
    out.commit();
    if (ext == ".msh") write_companion_opt(data, path, options);
  }
  if (parts.nb_parts > 0) report.notes.push_back(repartition_note(parts, parted, path));
  // Our own writers (and TetGen's files) hold the simplices and their constrained facets: the
  // elements kept verbatim from the input (a hybrid mesh's quadrangles and other cells, a planar
  // mesh's lines on no triangle) are not in them; Gmsh's writers keep them.
  if (own || is_tetgen(ext)) {
    long dropped = 0;
    for (const ElementBlock& b : data.model().extra)
      if (b.dim >= data.dim - 1 && b.medit_refs.empty())
        dropped += static_cast<long>(b.tags.size());
    if (dropped > 0)
      report.notes.push_back(
          std::to_string(dropped) +
          " elements kept from the input (quadrangles, prisms, pyramids, "
          "hexahedra, surfaces or curves bounding no cell) are not written to '" +
          path + "': its " + ext +
          " writer holds the triangles or tetrahedra and their boundary only; "
          "write a .msh (or a format Gmsh writes) to keep them");
  }
  return report;
}

}  // namespace cvtmesh
