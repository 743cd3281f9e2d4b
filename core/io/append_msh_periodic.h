// Gmsh 4.8's API can declare periodic entities but not their node correspondences, so the
// $Periodic section of a written .msh is appended by us: after Gmsh's $Elements, in the file's
// mode (ASCII or binary 4.1; in MSH 2.2 in text, as Gmsh writes it), from ModelInfo::periodic
// (node tags).
#pragma once
#include <string>
#include <vector>

#include "core/mesh/model_info.h"

namespace cvtmesh {

// Appends the section to the .msh at `path` (nothing if `links` is empty). Throws OutputError.
void append_msh_periodic(const std::string& path, const std::vector<PeriodicLink>& links,
                         double msh_version, bool binary);

}  // namespace cvtmesh
