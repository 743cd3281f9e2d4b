// The CLI's JSON (docs/cli.md, "JSON"): one object per mesh with the same keys in 2D and 3D,
// counts as integers; `stats` prints one, `compare` a list under "meshes", `optimize --report /
// --format json` an object with "before" and "after".
#pragma once
#include <nlohmann/json.hpp>

#include <string>

#include "core/pipeline/optimize.h"
#include "core/quality/quality_table.h"

namespace cvtmesh::cli {

inline constexpr const char* kJsonSchema = "cvtmesh/1";

// One mesh: the keys of QualityTable::to_json (new keys there pass through) with the dimension's
// names unified: q bins in both dimensions, min_angle / max_angle with "angle": "dihedral" (3D) or
// "planar" (2D); integer-valued counts as integers.
nlohmann::ordered_json mesh_json(const QualityStats& s);

// {"schema", "meshes": [mesh_json...]}.
nlohmann::ordered_json table_json(const QualityTable& t);

// optimize: {"schema", "command": "optimize", "input", "output", "method", ...,
//            "before": mesh_json, "after": mesh_json}.
nlohmann::ordered_json optimize_json(const OptimizeResult& r, const std::string& requested_method,
                                     const std::string& input, const std::string& output);

}  // namespace cvtmesh::cli
