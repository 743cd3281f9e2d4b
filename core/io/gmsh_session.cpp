#include "core/io/gmsh_session.h"

#include <gmsh.h>

#include <exception>
#include <mutex>
#include <new>
#include <string>
#include <vector>

#include "core/util/error.h"

namespace cvtmesh {
namespace {

std::mutex g_mutex;
bool g_external = false;
int g_depth = 0;  // nesting depth of our own sessions

}  // namespace

void set_gmsh_initialized_by_caller(bool yes) {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_external = yes;
}

GmshSession::GmshSession() {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (g_external) {
    owns_ = false;
    gmsh::option::getNumber("General.Terminal", terminal_);
  } else {
    if (g_depth == 0) gmsh::initialize(0, nullptr, false);
    ++g_depth;
    owns_ = true;
    terminal_ = 0;
  }
  gmsh::option::setNumber("General.Terminal", 0);
  // The logger keeps the messages for getLastError; start it once per initialization (starting
  // it twice, or in the caller's Gmsh, makes Gmsh warn "Logger already started").
  if (owns_ && g_depth == 1) gmsh::logger::start();
}

GmshSession::~GmshSession() {
  std::lock_guard<std::mutex> lock(g_mutex);
  try {
    if (owns_) {
      if (--g_depth == 0) {
        gmsh::logger::stop();
        gmsh::finalize();
      }
    } else {
      gmsh::option::setNumber("General.Terminal", terminal_);
    }
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
  } catch (const std::bad_alloc&) {
    // Gmsh sizes its arrays by the counts a file declares (found by fuzz/fuzz_msh.cpp): a
    // corrupt count asks for terabytes.
    throw InputError(context +
                     ": out of memory (the file declares more data than it can hold: "
                     "corrupt counts?)");
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
