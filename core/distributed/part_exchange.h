// How the ranks of a partitioned optimization (optimize_partitioned.h) share their parts: rank 0
// holds the mesh, scatters the parts (one byte buffer per rank) and gathers them back optimized.
// The collectives have a default through all_gather (every rank's buffer on every rank), which
// an exchange may override with point-to-point messages (MPI's does: a part goes to its rank
// only). SerialExchange is the one-rank case (every part optimized in this process); the MPI one
// lives in the front end (convert/mpi/), so that core/ does not depend on MPI.
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

class PartExchange {
 public:
  virtual ~PartExchange() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Every rank's buffer, on every rank, in rank order (a collective call: all ranks make it).
  virtual std::vector<std::vector<char>> all_gather(const std::vector<char>& mine) = 0;
  // Rank 0's buffer on every rank (the others' `from_root` is ignored).
  virtual std::vector<char> broadcast(const std::vector<char>& from_root);
  // Rank 0 gives one buffer per rank (per_rank.size() == size(); ignored elsewhere): each rank
  // gets its own.
  virtual std::vector<char> scatter(const std::vector<std::vector<char>>& per_rank);
  // Every rank's buffer on rank 0, in rank order; an empty list on the others.
  virtual std::vector<std::vector<char>> gather(const std::vector<char>& mine);
};

class SerialExchange : public PartExchange {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::vector<std::vector<char>> all_gather(const std::vector<char>& mine) override {
    return {mine};
  }
};

// The flat arrays of an optimized part (coordinates, classes, tags, tets, triangles; not the
// adjacency nor the model, which the receiver has from its own extraction), appended to `out`.
void pack_part(const TetMesh& mesh, std::vector<char>& out);
// Reads what pack_part wrote at out[pos...] into mesh's flat arrays (its model is left as it is)
// and advances pos. Throws InvariantError on a short or corrupt buffer.
void unpack_part(const std::vector<char>& in, std::size_t& pos, TetMesh& mesh);

// What every part's model shares with the whole mesh's (name, source, entities, physical groups,
// origin, the file's blocks, the order), without the element blocks, periodic links and mid-edge
// nodes (a part carries its own blocks: pack_blocks; its periodic nodes are pinned).
void pack_model(const ModelInfo& model, std::vector<char>& out);
void unpack_model(const std::vector<char>& in, std::size_t& pos, ModelInfo& model);
// A part's element blocks (model.extra).
void pack_blocks(const std::vector<ElementBlock>& blocks, std::vector<char>& out);
void unpack_blocks(const std::vector<char>& in, std::size_t& pos,
                   std::vector<ElementBlock>& blocks);

}  // namespace cvtmesh
