// cvtmesh-mpi: the same command line as cvtmesh, under MPI (`mpirun -n P cvtmesh-mpi optimize IN
// -o OUT --parts P`): a partitioned optimization runs part p on rank p mod P; rank 0 reads the
// input, sends each rank its parts, merges them, prints and writes (docs/scaling.md). Any other
// subcommand runs on every rank alike; use it on one rank.
#include <mpi.h>

#include <memory>

#include "convert/cli_common.h"
#include "convert/commands.h"
#include "convert/mpi/mpi_exchange.h"
#include "core/util/wait_policy.h"

int main(int argc, char** argv) {
  cvtmesh::prefer_passive_openmp_threads(argv);
  MPI_Init(&argc, &argv);
  cvtmesh::cli::exchange_factory() = [] {
    return std::unique_ptr<cvtmesh::PartExchange>(new cvtmesh::cli::MpiExchange());
  };
  const int rc = cvtmesh::cli::run_cli(argc, argv);
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  // A failed rank would leave the others waiting in a collective call: stop them all.
  if (rc != 0 && size > 1) MPI_Abort(MPI_COMM_WORLD, rc);
  MPI_Finalize();
  return rc;
}
