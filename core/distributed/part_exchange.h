// How the ranks of a partitioned optimization (optimize_partitioned.h) share their parts: each
// rank gives one byte buffer and gets every rank's, in rank order. SerialExchange is the one-rank
// case (every part optimized in this process); the MPI one lives in the front end
// (convert/mpi/), so that core/ does not depend on MPI.
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

}  // namespace cvtmesh
