#include "core/io/gmsh_session.h"

#include <gmsh.h>

#include <exception>
#include <string>
#include <vector>

#include "core/util/error.h"

namespace cvtmesh {

GmshSession::GmshSession() {
  // Gmsh 4.8 has no isInitialized(); before initialize() option getters leave their output
  // untouched, after it General.BuildInfo is never empty.
  bool initialized = false;
  try {
    std::string info;
    gmsh::option::getString("General.BuildInfo", info);
    initialized = !info.empty();
    if (initialized) gmsh::option::getNumber("General.Terminal", terminal_);
  } catch (...) {
    initialized = false;
  }
  if (!initialized) {
    gmsh::initialize(0, nullptr, false);
    owns_ = true;
    terminal_ = 0;
  }
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::logger::start();
}

GmshSession::~GmshSession() {
  try {
    gmsh::logger::stop();
    if (owns_)
      gmsh::finalize();
    else
      gmsh::option::setNumber("General.Terminal", terminal_);
  } catch (...) {
  }
}

void gmsh_checked(const std::string& context, const std::function<void()>& f) {
  std::string what;
  try {
    f();
    return;
  } catch (const InputError&) {
    throw;  // already a message for the user (not Gmsh's last logged error)
  } catch (const OutputError&) {
    throw;
  } catch (const InvariantError&) {
    throw;
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
  }
  std::string last;
  try {
    gmsh::logger::getLastError(last);
  } catch (...) {
  }
  if (last.empty()) last = what.empty() ? "unknown Gmsh error" : what;
  throw InputError(context + ": " + last);
}

}  // namespace cvtmesh
