// What a Gmsh model carries besides the simplices we optimize: entities with their boundaries,
// physical groups, lower-dimensional elements (points, lines), original node/element tags.
// Everything is kept so that .msh -> mesh -> .msh is exact.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/mesh/data_views.h"
#include "core/mesh/mid_edge_nodes.h"

namespace cvtmesh {

struct ModelEntity {
  int dim = 0;
  int tag = 0;
  std::vector<int> boundary;  // signed tags of the (dim-1) entities bounding it (Gmsh convention)
};

struct PhysicalGroup {
  int dim = 0;
  int tag = 0;
  std::string name;
  std::vector<int> entities;  // entity tags of dimension dim
};

// A block of elements kept verbatim (points, lines, or anything not optimized), on one entity.
struct ElementBlock {
  int dim = 0;
  int entity = 0;
  int gmsh_type = 0;              // Gmsh element type (15 = point, 1 = line, 2 = tri, 4 = tet)
  std::vector<std::size_t> tags;  // Gmsh element tags, #E
  std::vector<int> nodes;         // #E * nodes-per-element, 0-based vertex ids
  // #E references of a Medit .mesh's 3D Edges (written back by the Medit writer); empty for the
  // other blocks.
  std::vector<int> medit_refs;
};

// A periodic link of the mesh ($Periodic): entity (dim, tag) is the image of entity `master`
// by `affine` (16 values, row-major 4x4; may be empty), node by node (Gmsh node tags, which the
// writers keep).
struct PeriodicLink {
  int dim = 0;
  int tag = 0;
  int master = 0;
  std::vector<double> affine;
  std::vector<std::size_t> node_tags, master_node_tags;
};

// Where the elements came from: it decides which ones a .msh writer keeps, as Gmsh would save
// the model (core/io/select_msh_elements.h).
enum class ElementOrigin {
  kBuilt,     // read by our own readers (TetGen, Medit, VTK, surfaces) or built in memory: all
  kModel,     // meshed by Gmsh from a .geo / CAD model: the elements of its physical groups
  kMeshFile,  // read from a .msh (or another mesh file Gmsh opens): the blocks that file held
};

// A partitioned input (gmsh -part N, PartitionMesh; MSH 4.1 partition entities or MSH 2.2
// partition tags): it is read as its model (core/io/gmsh_partition_map.h) and a .msh output is
// partitioned again as it was (core/io/gmsh_repartition.h).
struct Partitioning {
  int nb_parts = 0;          // 0: not partitioned
  bool ghost_cells = false;  // ghost entities (Mesh.PartitionCreateGhostCells)
  bool topology = false;     // partition boundary entities (Mesh.PartitionCreateTopology)
  // The input's cells (tets in 3D, triangles in 2D) by element tag, sorted, and their parts
  // (1..nb_parts): whether an output kept the input's element-to-part assignment.
  std::vector<std::size_t> cell_tags;
  std::vector<int> cell_parts;
  // A partitioned .msh read unchanged: the mesh as read (partition_fingerprint) and the file's
  // size and modification time, so that a writer given the same mesh can keep the file's own
  // parts (cvtmesh convert) instead of cutting it anew.
  std::uint64_t mesh_fingerprint = 0;
  std::string source_stamp;
};

struct ModelInfo {
  std::string name;
  std::string source;                 // path of the file it came from ("" if built in memory)
  std::vector<ModelEntity> entities;  // all entities, every dimension
  std::vector<PhysicalGroup> groups;
  std::vector<ElementBlock> extra;     // elements of dimension < mesh dimension - 1
  std::vector<PeriodicLink> periodic;  // kept, their vertices fixed (core/mesh/pin_vertices.h)
  ElementOrigin origin = ElementOrigin::kBuilt;
  // kMeshFile: the (dim, entity tag, Gmsh element type) blocks the file held, before the reader
  // restored missing boundary facets (gmsh_missing_facets.h); sorted.
  std::vector<std::array<int, 3>> file_blocks;
  // An order-2 input: its mid-edge nodes (order 1 otherwise).
  MidEdgeNodes high_order;
  // What the reader did beyond reading (e.g. meshed the volumes of a surface-only file): one line
  // each, for the front ends to print as notes.
  std::vector<std::string> read_notes;
  // Tets the reader turned positive (the file gave them with negative volume: reorient_tets.h);
  // in 2D, triangles turned to their surface's majority turning sense (gmsh_model.cpp).
  long nb_reoriented = 0;
  // The file's post-processing views ($NodeData / $ElementData), each for the mesh it was read or
  // carried onto (DataView::fingerprint).
  std::vector<DataView> views;
  // A partitioned input: how many parts, and what else its file held (nb_parts 0 otherwise).
  Partitioning partitioning;
};

}  // namespace cvtmesh
