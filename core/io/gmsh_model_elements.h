// The mesh elements of the current Gmsh model, entity by entity, as the model's: in a
// partitioned model (gmsh_partition_map.h) the elements of the partition entities are their
// parents', in the order of the element tags, as in the unpartitioned file; ghost cells and the
// interfaces between parts are skipped. Requires a live GmshSession.
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "core/io/gmsh_partition_map.h"

namespace cvtmesh {

struct GmshEntityElements {
  int dim = 0, tag = 0;    // a model entity
  std::vector<int> types;  // Gmsh element types, in the order they were met
  std::vector<std::vector<std::size_t>> tags, nodes;  // per type: #E element tags, #E * n node tags
  std::vector<std::vector<int>> parts;  // per type, a partitioned model's: #E parts (0: none)
};

// The elements of `entities` (dim, tag) (an unpartitioned model: each entity's, in Gmsh's order;
// a partitioned one: per model entity, in the order of its own or first partition entity among
// `entities`, each type sorted by element tag). Entities without elements are left out.
std::vector<GmshEntityElements> read_model_elements(
    const std::vector<std::pair<int, int>>& entities, const GmshPartitionMap& map);

}  // namespace cvtmesh
