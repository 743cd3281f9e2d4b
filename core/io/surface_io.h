// Triangulated surfaces (.off .obj .ply .stl) through OpenMesh.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/mesh_data.h"
#include "core/util/error.h"

namespace cvtmesh {

struct SurfaceMesh {
  std::vector<double> xyz;  // #V by 3
  std::vector<int> tris;    // #F by 3, 0-based vertex ids, consistently oriented
};

// The surface a surface format can hold. 3D: the triangles on the domain boundary (faces of a
// single tet), oriented outwards (right-hand normal away from the tet); interfaces between regions
// are interior and left out. 2D: the triangles themselves, counter-clockwise, at z = z0.
// Only the vertices the triangles use are kept.
SurfaceMesh boundary_surface(const MeshData& data);

// Thrown by our readers of mesh formats (Medit .mesh, VTK) for a file that holds triangles in
// space and no tetrahedra: read_mesh has Gmsh mesh the inside when they close up (gmsh_surface.h),
// and passes the error on otherwise. `surface`: the triangles, only the vertices they use.
class SurfaceOnlyInput : public InputError {
 public:
  SurfaceOnlyInput(const std::string& message, SurfaceMesh s)
      : InputError(message), surface(std::move(s)) {}
  SurfaceMesh surface;
};

// The surface of the triangles `tris` (vertex ids into xyz, 3 coordinates each), only the
// vertices they use kept (in the order of first use). Ids must be in range.
SurfaceMesh used_surface(const std::vector<double>& xyz, const std::vector<int>& tris);

// Throws InputError if a triangle's vertex id is out of range, else SurfaceOnlyInput ("<what>
// has no tetrahedra and its triangles are not in a plane z = const ...") with their surface.
[[noreturn]] void throw_surface_only(const std::string& what, const std::vector<double>& xyz,
                                     const std::vector<int>& tris);

// Writes boundary_surface(data) with OpenMesh, format by the extension of `path` (ASCII; binary
// for STL). OpenMesh 9 stores surface coordinates in single precision, in every format. Throws
// InputError if the surface is non-manifold (OpenMesh cannot hold it), OutputError if the file
// cannot be written.
void write_surface(const MeshData& data, const std::string& path);

// Reads a triangulated surface with OpenMesh (polygons are split into triangles; coordinates in
// single precision as OpenMesh 9 reads them, except ASCII .off/.obj: double,
// read_surface_coordinates.h). Rejects with an
// InputError naming the file: unreadable or garbage files, faces with invalid or repeated vertex
// ids, non-finite coordinates, non-manifold or inconsistently oriented surfaces, and, if
// `require_closed`, surfaces with boundary edges (open). Vertices no face uses are dropped.
SurfaceMesh read_surface(const std::string& path, bool require_closed);

}  // namespace cvtmesh
