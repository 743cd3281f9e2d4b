// Medit / INRIA ASCII .mesh files (MMG, Medit, FreeFem, Gmsh read them).
#pragma once
#include <string>

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// Writes `MeshVersionFormatted 2`: 3D: Dimension 3, Vertices (ref 0), Triangles (ref = surface
// tag), the Edges read from a .mesh (line blocks with medit_refs, as they were), Tetrahedra
// (ref = region tag); 2D: Dimension 2, Vertices, Edges (ref = curve tag),
// Triangles (ref = region tag, counter-clockwise). Exact coordinates (17 digits).
// Throws OutputError if the file cannot be written.
void write_medit(const MeshData& data, const std::string& path);

// Reads an ASCII .mesh: Vertices, Edges, Triangles, Tetrahedra with their refs (keywords in any
// case; 3D Edges are kept as line blocks in model.extra, one curve entity per ref, with their
// refs in ElementBlock::medit_refs; Corners, Ridges, Required*, Normals, Tangents and their
// *AtVertices are skipped). A Dimension 3 file without tetrahedra whose triangles lie in a plane z
// = const is read as a 2D mesh. Refs are the region / surface / curve tags (ref <= 0 facets: see
// finish_mesh). Throws InputError naming the file and line (truncated file, garbage, index out of
// range, unsupported element type, inverted element...).
MeshData read_medit(const std::string& path);

}  // namespace cvtmesh
