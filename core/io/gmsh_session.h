// The Gmsh SDK is a process-wide singleton. GmshSession initializes it when needed (and then
// finalizes it), or reuses the caller's session (in-process Python/C++ scripting), silencing the
// terminal and capturing the log so that errors become typed exceptions.
#pragma once
#include <functional>
#include <string>

namespace cvtmesh {

class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
  bool owns() const { return owns_; }

 private:
  bool owns_ = false;
  double terminal_ = 0;
};

// Runs f (Gmsh calls); a Gmsh error (thrown or logged) becomes InputError("<context>: <message>").
void gmsh_checked(const std::string& context, const std::function<void()>& f);

}  // namespace cvtmesh
