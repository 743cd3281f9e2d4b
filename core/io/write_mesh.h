// Writes a mesh, format by extension: .msh (4.1, or 2.2), .vtk/.vtu, .node (TetGen .node/.ele/
// .face), .mesh (Medit), .off/.obj/.ply/.stl (boundary surface, OpenMesh), and other Gmsh formats.
// Atomic: a temporary in the target directory is renamed over the target only when complete.
#pragma once
#include <string>
#include <vector>

#include "core/io/atomic_file.h"
#include "core/mesh/mesh_data.h"

namespace cvtmesh {

inline constexpr const char* kUnassignedGroup = "cvtmesh:unassigned";

struct WriteOptions {
  double msh_version = 4.1;          // 4.1 or 2.2
  bool binary = false;               // binary .msh
  std::vector<ElementField> fields;  // per-element data ($ElementData / VTK cell data)
  OutputPolicy policy;
};

// MSH 2.2 keeps physical groups only on elements that belong to one: entities in no group are
// written in an extra group named kUnassignedGroup, which read_mesh drops.
// Throws OutputError (cannot write, refused) or InputError (format cannot hold this mesh).
void write_mesh(const MeshData& data, const std::string& path, const WriteOptions& options = {});

// What write_mesh would refuse without looking at the mesh, checked before a long computation:
// no or unknown extension, per-element data the format cannot hold, the output policy (existing
// file, the input itself, a directory), a missing or read-only directory. Throws OutputError.
void check_can_write(const std::string& path, const WriteOptions& options = {});

// The extensions write_mesh understands, for --help.
std::string supported_write_formats();

}  // namespace cvtmesh
