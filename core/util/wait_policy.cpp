#include "core/util/wait_policy.h"

#include <unistd.h>

#include <cstdlib>

namespace cvtmesh {

void prefer_passive_openmp_threads(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv("/proc/self/exe", argv);
  // Not replaced (no /proc): the program goes on with the policy it was loaded with.
}

}  // namespace cvtmesh
