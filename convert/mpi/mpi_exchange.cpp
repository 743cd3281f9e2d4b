#include "convert/mpi/mpi_exchange.h"

#include <mpi.h>

#include <algorithm>
#include <cstdint>

namespace cvtmesh::cli {

MpiExchange::MpiExchange() {
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

namespace {

constexpr std::uint64_t kChunk = std::uint64_t{1} << 30;

void send(const std::vector<char>& b, int to) {
  const std::uint64_t n = b.size();
  MPI_Send(&n, 1, MPI_UINT64_T, to, 0, MPI_COMM_WORLD);
  for (std::uint64_t off = 0; off < n; off += kChunk)
    MPI_Send(b.data() + off, static_cast<int>(std::min(kChunk, n - off)), MPI_CHAR, to, 1,
             MPI_COMM_WORLD);
}

std::vector<char> receive(int from) {
  std::uint64_t n = 0;
  MPI_Recv(&n, 1, MPI_UINT64_T, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  std::vector<char> b(n);
  for (std::uint64_t off = 0; off < n; off += kChunk)
    MPI_Recv(b.data() + off, static_cast<int>(std::min(kChunk, n - off)), MPI_CHAR, from, 1,
             MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return b;
}

}  // namespace

std::vector<char> MpiExchange::broadcast(const std::vector<char>& from_root) {
  std::uint64_t n = rank_ == 0 ? from_root.size() : 0;
  MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  std::vector<char> b = rank_ == 0 ? from_root : std::vector<char>(n);
  for (std::uint64_t off = 0; off < n; off += kChunk)
    MPI_Bcast(b.data() + off, static_cast<int>(std::min(kChunk, n - off)), MPI_CHAR, 0,
              MPI_COMM_WORLD);
  return b;
}

std::vector<char> MpiExchange::scatter(const std::vector<std::vector<char>>& per_rank) {
  if (rank_ != 0) return receive(0);
  for (int k = 1; k < size_; ++k) send(per_rank.at(k), k);
  return per_rank.at(0);
}

std::vector<std::vector<char>> MpiExchange::gather(const std::vector<char>& mine) {
  if (rank_ != 0) {
    send(mine, 0);
    return {};
  }
  std::vector<std::vector<char>> all(size_);
  all[0] = mine;
  for (int k = 1; k < size_; ++k) all[k] = receive(k);
  return all;
}

std::vector<std::vector<char>> MpiExchange::all_gather(const std::vector<char>& mine) {
  const std::uint64_t n = mine.size();
  std::vector<std::uint64_t> sizes(size_);
  MPI_Allgather(&n, 1, MPI_UINT64_T, sizes.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD);
  std::vector<std::vector<char>> all(size_);
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
