// cvtmesh: the command-line front end (convert/run_cli.cpp); a partitioned optimization
// (`optimize --parts`) runs its parts in turn in this process.
#include "convert/commands.h"
#include "core/util/wait_policy.h"

int main(int argc, char** argv) {
  cvtmesh::prefer_passive_openmp_threads(argv);
  return cvtmesh::cli::run_cli(argc, argv);
}
