// Triangulated surfaces (.off .obj .ply .stl) through OpenMesh.
#pragma once
#include <string>
#include <vector>

#include "core/mesh/mesh_data.h"

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
