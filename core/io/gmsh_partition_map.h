// A partitioned Gmsh model (gmsh -part N, PartitionMesh, t21) seen as its model. Gmsh moves the
// mesh of every model entity into partition entities, one per part it meets, whose parent
// (gmsh::model::getParent) is that model entity; with Mesh.PartitionCreateTopology the
// interfaces between parts inside a model entity become partition entities of their own, whose
// parent is of a higher dimension; with Mesh.PartitionCreateGhostCells ghost entities hold copies
// of the neighbouring parts' cells. Read as the model: the elements of a partition entity are its
// parent's, ghost cells and the elements of the interfaces between parts are skipped, nodes are
// classified on the parents. Requires a live GmshSession.
#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/model_info.h"

namespace cvtmesh {

using GmshDimTag = std::pair<int, int>;

struct GmshPartitionMap {
  // nb_parts, ghost_cells, topology (the cell tags and parts are filled by mesh_from_gmsh); an
  // unpartitioned model: nb_parts 0 and no roles.
  Partitioning partitioning;
  // The partition and ghost entities; an entity not listed is one of the model.
  struct Role {
    GmshDimTag parent{-1, -1};  // the model entity (resolved through parents of parents)
    bool elements = false;      // its elements are its parent's (else skipped: ghost, interface)
    bool ghost = false;
    int part = 0;  // its part, for an entity of one part (0 otherwise)
  };
  std::map<GmshDimTag, Role> roles;

  bool partitioned() const { return partitioning.nb_parts > 0; }
  // False for the partition and ghost entities, which are not entities of the model.
  bool is_model_entity(int dim, int tag) const { return !roles.count({dim, tag}); }
  // The model entity that owns the elements of (dim, tag), or {-1, -1} if they are not the
  // model's (ghost cells, the interface between two parts inside a model entity).
  GmshDimTag element_owner(int dim, int tag) const;
  // The model entity that owns the nodes classified on (dim, tag) (an interface between parts
  // inside a volume: that volume).
  GmshDimTag node_owner(int dim, int tag) const;
  // The model's physical groups: partition entities replaced by their parents, the interfaces
  // between parts dropped, groups left empty dropped (Gmsh 4.8 gives an interface inside a
  // volume the volume's groups, in the interface's dimension).
  void map_groups(std::vector<PhysicalGroup>& groups) const;
};

// Reads the partition and ghost entities of the current Gmsh model. `file_parts`: the number of
// parts a file's header declares ($PartitionedEntities), 0 if unknown. Throws InputError naming
// `what` when some parts hold no cells: one file of a mesh saved one file per part
// (gmsh -part_split, Mesh.PartitionSplitMeshFiles), which is not a mesh of the model.
GmshPartitionMap read_gmsh_partition_map(const std::string& what, int file_parts = 0);

}  // namespace cvtmesh
