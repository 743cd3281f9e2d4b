// TetGen's .node/.ele/.face files (3D) and their 2D counterpart, Triangle's .node/.ele/.edge.
#pragma once
#include <string>
#include <vector>

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// The files of one TetGen/Triangle mesh: X.node, X.ele and X.face (3D) or X.edge (2D).
struct TetgenFiles {
  std::string node, ele, facets;
};
// From X.node or X.ele (or X.face/X.edge): the three names for a mesh of dimension dim.
TetgenFiles tetgen_files(const std::string& path, int dim);

// Writes the three files (exact coordinates, 1-based indices). 3D: .ele holds the tets with the
// region tag as first attribute and one more attribute per field; .face the boundary and
// interface triangles with their surface tag as marker. 2D: Triangle's format, .edge with the
// curve tags as markers. Throws OutputError if a file cannot be written.
void write_tetgen(const MeshData& data, const TetgenFiles& files,
                  const std::vector<ElementField>& fields);

// Reads X.node + X.ele [+ X.face / X.edge] given any of them. The dimension comes from the .node
// header (3: TetGen, 2: Triangle). The first .ele attribute is the region tag (default 1). Without
// a .face/.edge file (or for unmarked facets) the boundary gets marker 1 and interfaces between
// regions a fresh marker; see finish_mesh. Throws InputError naming the file and line.
MeshData read_tetgen(const std::string& path);

}  // namespace cvtmesh
