// The $Periodic section of an MSH 2.2 file. Gmsh 4.8 writes it (after $Elements, in text even in
// a binary file) but does not give it back through its API when it reads such a file
// (getPeriodicNodes is empty), so read_mesh reads it here. Format: the number of links; per link
// "dim tag master", an optional "Affine a0 .. a15" line, the number of node pairs, one
// "node masterNode" (Gmsh node tags) a line.
#pragma once
#include <string>
#include <vector>

#include "core/mesh/model_info.h"

namespace cvtmesh {

// The links of the first $Periodic section of the .msh at `path` (empty: none). Throws
// InputError naming the file and the line on a malformed section.
std::vector<PeriodicLink> read_msh2_periodic(const std::string& path);

}  // namespace cvtmesh
