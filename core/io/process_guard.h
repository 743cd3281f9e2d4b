// The second line of defence of the .geo scan (geo_scan.h): while a ProcessGuard is alive, the
// process's system() and popen() — what Gmsh's SystemCall, NonBlockingSystemCall and OnelabRun
// call — refuse to start anything and record the command instead. cvtmesh defines these two C
// functions in its own code; in an executable that links this file they take precedence over
// libc's for every library, libgmsh included (outside a guard they forward to libc's). In a
// process whose executable is not ours (Python), only the scan applies.
#pragma once
#include <string>
#include <vector>

namespace cvtmesh {

class ProcessGuard {
 public:
  ProcessGuard();   // refuses from now on (nests)
  ~ProcessGuard();  // back to the previous state
  ProcessGuard(const ProcessGuard&) = delete;
  ProcessGuard& operator=(const ProcessGuard&) = delete;
  // The commands refused while this guard was alive, in order.
  std::vector<std::string> refused() const;

 private:
  std::size_t first_;
};

}  // namespace cvtmesh
