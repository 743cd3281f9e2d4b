#include "core/pipeline/volumes_apart.h"

#include <algorithm>

#include "core/mesh/extract_regions.h"
#include "core/pipeline/find_structural_defects.h"

namespace cvtmesh {

std::vector<int> volumes_defective_only_together(const TetMesh& mesh, double relative_tolerance) {
  std::vector<int> tags;
  for (int t = 0; t < mesh.nb_tets(); ++t)
    if (mesh.tets[4 * static_cast<std::size_t>(t)] >= 0) tags.push_back(mesh.tet_region[t]);
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  if (tags.size() < 2 || find_structural_defects(mesh, relative_tolerance).empty()) return {};
  // The tolerance is relative to each volume's own diagonal there; a volume much smaller than
  // the whole gets a tighter absolute one, which only finds fewer coincidences.
  for (int t : tags)
    if (!find_structural_defects(extract_regions(mesh, {t}).mesh, relative_tolerance).empty())
      return {};
  return tags;
}

}  // namespace cvtmesh
