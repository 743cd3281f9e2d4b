// The volumes an optimization is restricted to (OptimizeOptions::regions, ::physical): the
// region tags named by a list of volume entity tags and/or a volume physical group's name.
#pragma once
#include <string>
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// The sorted region tags selected in mesh: those of `regions` ("1,3" or "1 3"; "" = none given)
// and the volumes of the 3D physical group named `physical` ("" = none given). Empty if neither
// is given (no selection: everything). Throws OptionError for a malformed list, a tag no tet
// carries or an unknown group, listing the available ones.
std::vector<int> select_regions(const TetMesh& mesh, const std::string& regions,
                                const std::string& physical);

// Parses "1,3" / "1 3" into tags; throws OptionError (option `regions`) if it is not a list of
// integers. "" gives no tags.
std::vector<int> parse_region_tags(const std::string& regions);

}  // namespace cvtmesh
