// The Gmsh SDK is a process-wide singleton. GmshSession initializes it for the duration of a
// scope (nested sessions share one initialization), silences the terminal and captures the log so
// that errors become typed exceptions. Front ends that run inside a program which initialized Gmsh
// itself (Python `import gmsh`, the GUI) declare it with set_gmsh_initialized_by_caller(true):
// then sessions never initialize or finalize.
//
// Gmsh 4.8 has no isInitialized(), and calling any API function before initialize() corrupts its
// option defaults (the optimizer silently does nothing afterwards), so this cannot be probed.
#pragma once
#include <functional>
#include <string>

namespace cvtmesh {

void set_gmsh_initialized_by_caller(bool yes);

class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
  // True if this session (or an enclosing one of ours) initialized Gmsh: the models it creates
  // can be discarded freely; false inside a caller's Gmsh (do not touch the caller's models).
  bool owns() const { return owns_; }

 private:
  bool owns_ = false;
  double terminal_ = 0;
};

// Runs f (Gmsh calls); a Gmsh error (thrown or logged) becomes InputError("<context>: <message>").
void gmsh_checked(const std::string& context, const std::function<void()>& f);

}  // namespace cvtmesh
