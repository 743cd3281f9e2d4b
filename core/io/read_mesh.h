// Reads a mesh from a file, by extension: .msh (2.2/4.1) and whatever Gmsh opens (.geo is meshed
// by Gmsh in the model's dimension; .step/.brep/...); TetGen .node/.ele, Medit .mesh and VTK
// .vtk/.vtu by our own readers (core/io/*_io.h); .stl/.off/.obj/.ply through OpenMesh (a closed
// surface is tetrahedralized by Gmsh, see gmsh_surface.h; with dim 2 a planar one is read as a
// 2D mesh). A .msh that lacks the boundary triangles of surfaces outside its physical groups gets
// them back (gmsh_missing_facets.h).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

struct ReadOptions {
  int dim = -1;               // 2, 3, or -1: the highest dimension present / the model's
  bool gmsh_optimize = true;  // when Gmsh meshes a model: run its default optimizer (Mesh.Optimize)
  double mesh_size_factor = 0;  // >0: Mesh.MeshSizeFactor for models meshed by Gmsh
  int seed = 0;                 // Mesh.RandomSeed (reproducible meshing)
  // Numbers set before a .geo is parsed (like gmsh -setnumber NAME VALUE), e.g. {"h", 0.1}.
  std::vector<std::pair<std::string, double>> set_numbers;
  // Strings set the same way (like gmsh -setstring NAME VALUE), e.g. {"stl", "/data/femur.stl"}.
  std::vector<std::pair<std::string, std::string>> set_strings;
  // A script Gmsh parses (.geo, and whatever it Includes or Merges) may start programs
  // (SystemCall, NonBlockingSystemCall, OnelabRun) only if this is true: otherwise it is scanned
  // first and refused with InputError naming the file, line and command (geo_scan.h), and any
  // attempt the scan missed is blocked while Gmsh parses (process_guard.h).
  bool allow_system_calls = false;
};

// Throws InputError with a message naming the file and the problem.
MeshData read_mesh(const std::string& path, const ReadOptions& options = {});

// True if read_mesh has Gmsh open the file as a model and mesh it (.geo, .step, .brep, ...: not
// a mesh file, not a surface file). Read inside an enclosing GmshSession, such a model stays the
// current Gmsh model after read_mesh returns, with its CAD (gmsh_cad_boundary.h) until that
// session ends.
bool read_mesh_meshes_a_model(const std::string& path);

// Lower-case extension with the dot (".msh"), or "" if none.
std::string file_extension(const std::string& path);

}  // namespace cvtmesh
