// The pipeline on a partitioned mesh (docs/scaling.md, ParMmg's scheme): the tets are cut into
// parts (partition_tets.h), each part is optimized alone with its interface pinned
// (extract_tets, then optimize(): with the default free boundary, the part's share of the
// model's boundary moves on the part's own boundary triangles, without surface coarsening, each
// round within 1/rounds of the Hausdorff and volume bounds), the parts are put back
// (merge_parts), and the next round cuts elsewhere -- away from the previous round's interface --
// so that no vertex stays frozen in every round. Rank 0 holds the mesh: it cuts it, sends each
// rank of a PartExchange its parts (part p to rank p mod size), gets them back optimized and
// merges them; the other ranks hold their parts only. The result does not depend on the number
// of ranks.
#pragma once
#include <string>
#include <vector>

#include "core/distributed/part_exchange.h"
#include "core/pipeline/optimize.h"

namespace cvtmesh {

struct PartitionOptions {
  int parts = 2;   // parts per round (at least 1; at most the tets)
  int rounds = 2;  // rounds of partition, optimization and merge
};

struct PartitionRound {
  int nb_cut_faces = 0;        // interface faces of this round's partition
  int nb_avoided_cut = 0;      // of those, touching the previous round's interface
  int nb_interface = 0;        // vertices pinned as interface this round
  std::vector<int> part_tets;  // tets per part, before optimization
  double seconds = 0;          // this rank's wall time in the round
  QualityStats after;          // the merged mesh after the round
};

struct PartitionedResult {
  QualityStats before, after;
  std::vector<PartitionRound> rounds;
  // Interior vertices of the input pinned in every round (frozen throughout; 0 with two rounds or
  // more unless METIS could not avoid the previous interface).
  int nb_frozen_every_round = 0;
  bool kept_input = false;  // the result was worse than the input: the input is returned
  std::vector<std::string> notes;
  double seconds = 0;
};

// Optimizes mesh in place on rank 0; every rank of `exchange` calls it with the same options,
// rank 0 with the mesh (the others' `mesh` is neither read nor changed: give an empty one; their
// result holds each round's seconds only).
// options.method applies to each part (options.boundary_model is not used: the discrete
// geometry; regions/physical selections are refused). Throws InputError for bad
// options, InvariantError if a part or the merged mesh breaks an invariant (check_mesh).
PartitionedResult optimize_partitioned(TetMesh& mesh, const OptimizeOptions& options,
                                       const PartitionOptions& partition, PartExchange& exchange);

}  // namespace cvtmesh
