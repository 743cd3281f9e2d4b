// Writes a mesh, format by extension: .msh (4.1, or 2.2), .vtk/.vtu, .node (TetGen .node/.ele/
// .face), .mesh (Medit), .off/.obj/.ply/.stl (boundary surface, OpenMesh), and other Gmsh formats.
// Atomic: a temporary in the target directory is renamed over the target only when complete.
#pragma once
#include <string>
#include <vector>

#include "core/io/atomic_file.h"
#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// The placeholder group of the MSH 2.2 files of cvtmesh 0.1 (elements in no group); read_mesh
// drops it. No longer written.
inline constexpr const char* kUnassignedGroup = "cvtmesh:unassigned";

struct WriteOptions {
  double msh_version = 4.1;          // 4.1 or 2.2
  bool binary = false;               // binary .msh
  bool save_all = false;             // .msh: every element, not only what Gmsh would save
  std::vector<ElementField> fields;  // per-element data ($ElementData / VTK cell data)
  OutputPolicy policy;
};

// A .msh holds the elements Gmsh would save (core/io/select_msh_elements.h: the physical groups'
// of a model, the blocks a .msh input held; everything with save_all). MSH 2.2 cannot hold
// elements outside physical groups next to groups: refused (OutputError) rather than invent one.
// With fields, the $ElementData covers every written element (NaN on those that are not cells of
// the mesh dimension), elements numbered in file order, and a companion PATH.opt (which Gmsh
// merges when it opens PATH) shows the first field alone over the range of its values; a stale
// PATH.opt of ours is removed when writing without fields, a user's own is left alone. A
// partitioned output's $ElementData covers its cells only, by their tags (the file's order is the
// parts').
// A partitioned input (ModelInfo::partitioning) is written to a .msh partitioned again into as
// many parts (core/io/gmsh_repartition.h), to other formats unpartitioned; the returned notes say
// which, for the front ends to print.
// Throws OutputError (cannot write, refused) or InputError (format cannot hold this mesh).
struct WriteReport {
  std::vector<std::string> notes;
};
WriteReport write_mesh(const MeshData& data, const std::string& path,
                       const WriteOptions& options = {});

// What write_mesh would refuse without looking at the mesh, checked before a long computation:
// no or unknown extension, per-element data the format cannot hold, the output policy (existing
// file, the input itself, a directory), a missing or read-only directory. Throws OutputError.
void check_can_write(const std::string& path, const WriteOptions& options = {});

// The extensions write_mesh understands, for --help.
std::string supported_write_formats();

}  // namespace cvtmesh
