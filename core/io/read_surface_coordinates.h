// OpenMesh 9's readers store coordinates in single precision whatever the mesh traits (its OFF,
// OBJ, STL and PLY readers parse into Vec3f): a model moved by 1e5 then loses its shape (relative
// 7e-8). The vertex coordinates of an ASCII .off, .obj or .stl and of an ASCII or binary
// little-endian .ply, read again here in double precision in OpenMesh's vertex order, replace
// them. (A binary .stl holds single precision: nothing is lost. An ASCII .stl's corners that
// differ only beyond single precision are still merged into one vertex, as OpenMesh does.)
#pragma once
#include <string>
#include <vector>

namespace cvtmesh {

// #V by 3 coordinates of the vertices of the file, in OpenMesh's order; empty if the file is of
// another format or mode, or not understood (the caller then keeps OpenMesh's).
std::vector<double> read_surface_coordinates(const std::string& path);

}  // namespace cvtmesh
