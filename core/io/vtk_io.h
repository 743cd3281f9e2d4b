// VTK unstructured grids: legacy ASCII .vtk and XML ASCII .vtu (ParaView, VisIt, meshio).
#pragma once
#include <string>
#include <vector>

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// Writes the tets (3D, VTK_TETRA) or the triangles (2D, VTK_TRIANGLE, z = z0) with cell data
// "region" (the region / surface tag) and one double array per field (in element order).
// Legacy array names cannot hold blanks: they become '_' in .vtk (kept in .vtu).
// Throws OutputError if the file cannot be written.
void write_vtk(const MeshData& data, const std::string& path,
               const std::vector<ElementField>& fields);
void write_vtu(const MeshData& data, const std::string& path,
               const std::vector<ElementField>& fields);

// Reads an ASCII unstructured grid. With tetrahedra: a 3D mesh (triangle cells become boundary
// triangles); otherwise the triangles must lie in a plane z = const and form a 2D mesh (line cells
// become boundary edges). The cell array "region" gives the region/surface/curve tags (default:
// 1 for the elements, boundary from the complex, see finish_mesh). Other one-component cell
// arrays are returned in *fields (values of the main elements, in element order) if given.
// Throws InputError naming the file and line (binary/compressed data, unsupported cell types,
// truncated or garbage input...).
MeshData read_vtk(const std::string& path, std::vector<ElementField>* fields = nullptr);
MeshData read_vtu(const std::string& path, std::vector<ElementField>* fields = nullptr);

}  // namespace cvtmesh
