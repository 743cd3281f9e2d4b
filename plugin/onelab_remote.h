// The ONELAB tree of a stock Gmsh that launched us as a ONELAB client (Solver.Name0 /
// Solver.Executable0): Gmsh runs `client -onelab NAME SOCKET` for each of its actions
// (initialize, check, compute) and the client talks to it over the socket. Uses the header-only
// client of gmsh-doc (solvers/c++/onelab.h, GmshSocket.h), not the Gmsh SDK: libgmsh exports
// its own, layout-incompatible onelab:: classes, so the header's namespaces are renamed.
#pragma once
#include <memory>
#include <string>

#include "plugin/gmsh_gui.h"

namespace cvtmesh::plugin {

class RemoteOnelab : public OnelabTree {
 public:
  // Connects to the Gmsh named on the command line (-onelab NAME SOCKET); nullptr if the command
  // line has no -onelab, InputError if the connection fails.
  static std::unique_ptr<RemoteOnelab> connect(int argc, char** argv);
  ~RemoteOnelab() override;

  const std::string& name() const { return name_; }
  // What Gmsh asks for: the string NAME/Action ("initialize", "check", "compute", ...).
  std::string action();

  void set(const OnelabParam& p) override;
  std::optional<double> number(const std::string& name) override;
  std::optional<std::string> string(const std::string& name) override;
  void info(const std::string& message) override;
  void error(const std::string& message) override;
  void progress(const std::string& message) override;

  // Has the GUI parse .geo-language text ("Delete Model; Merge \"f.msh\";", options, ...).
  void parse_string(const std::string& text);

 private:
  struct Impl;
  RemoteOnelab(std::string name, std::unique_ptr<Impl> impl);
  std::string name_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cvtmesh::plugin
