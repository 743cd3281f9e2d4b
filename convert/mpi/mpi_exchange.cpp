#include "convert/mpi/mpi_exchange.h"

#include <mpi.h>

#include <algorithm>
#include <cstdint>

namespace cvtmesh::cli {

MpiExchange::MpiExchange() {
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

std::vector<std::vector<char>> MpiExchange::all_gather(const std::vector<char>& mine) {
  const std::uint64_t n = mine.size();
  std::vector<std::uint64_t> sizes(size_);
  MPI_Allgather(&n, 1, MPI_UINT64_T, sizes.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD);
  std::vector<std::vector<char>> all(size_);
  constexpr std::uint64_t kChunk = std::uint64_t{1} << 30;
  for (int k = 0; k < size_; ++k) {
    all[k] = k == rank_ ? mine : std::vector<char>(sizes[k]);
    for (std::uint64_t off = 0; off < sizes[k]; off += kChunk) {
      const int count = static_cast<int>(std::min(kChunk, sizes[k] - off));
      MPI_Bcast(all[k].data() + off, count, MPI_CHAR, k, MPI_COMM_WORLD);
    }
  }
  return all;
}

}  // namespace cvtmesh::cli
