// OpenMesh 9's readers store coordinates in single precision whatever the mesh traits (its OFF and
// OBJ readers parse into Vec3f): a model moved by 1e5 then loses its shape (relative 7e-8). The
// vertex coordinates of an ASCII .off or .obj, read again here in double precision, in file order
// (OpenMesh's vertex order), replace them.
#pragma once
#include <string>
#include <vector>

namespace cvtmesh {

// #V by 3 coordinates of the vertices of an ASCII .off / .obj file, in file order; empty if the
// file is of another format, binary, or not understood (the caller then keeps OpenMesh's).
std::vector<double> read_surface_coordinates(const std::string& path);

}  // namespace cvtmesh
