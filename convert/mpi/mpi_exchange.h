// The PartExchange of cvtmesh-mpi: the ranks of MPI_COMM_WORLD.
#pragma once
#include "core/distributed/part_exchange.h"

namespace cvtmesh::cli {

class MpiExchange : public PartExchange {
 public:
  MpiExchange();
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  // Sizes by MPI_Allgather, then each rank's buffer broadcast from it in chunks of at most 1 GB
  // (MPI counts are ints).
  std::vector<std::vector<char>> all_gather(const std::vector<char>& mine) override;
  // The size, then the buffer in chunks (MPI_Bcast).
  std::vector<char> broadcast(const std::vector<char>& from_root) override;
  // Point to point: rank 0 sends rank k its buffer only (MPI_Send / MPI_Recv, size then chunks),
  // and receives each rank's in rank order.
  std::vector<char> scatter(const std::vector<std::vector<char>>& per_rank) override;
  std::vector<std::vector<char>> gather(const std::vector<char>& mine) override;

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace cvtmesh::cli
