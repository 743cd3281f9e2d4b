#include "core/util/wait_policy.h"

#include <unistd.h>

#include <cstdlib>

namespace cvtmesh {

void prefer_passive_openmp_threads(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  // The program's own file (readlink rather than exec of /proc/self/exe itself: under a tool
  // such as valgrind the link names the program, not the tool).
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) return;
  self[n] = '\0';
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv(self, argv);
  // Not replaced: the program goes on with the policy it was loaded with.
}

}  // namespace cvtmesh
