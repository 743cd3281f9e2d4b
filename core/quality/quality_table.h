// QualityTable: several meshes side by side as columns (Init | CombOpt | CVDT | CVDT+SWAP), with
// exactly the rows of the paper's Table 6/7 (3D) or Tables 1-5 (2D), printed as aligned text,
// Markdown or JSON.
#pragma once
#include <string>
#include <vector>

#include "core/quality/quality_stats.h"

namespace cvtmesh {

struct QualityTable {
  std::vector<QualityStats> columns;

  std::string to_text() const;
  std::string to_markdown() const;
  std::string to_json() const;
};

}  // namespace cvtmesh
