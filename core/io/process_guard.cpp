#include "core/io/process_guard.h"

#include <dlfcn.h>
#include <errno.h>

#include <atomic>
#include <cstdio>
#include <mutex>

namespace cvtmesh {
namespace {

std::atomic<int> g_depth{0};
std::mutex g_mutex;
std::vector<std::string>& refused_commands() {
  static std::vector<std::string> v;
  return v;
}

bool refuse(const char* command) {
  if (g_depth.load() == 0) return false;
  std::lock_guard<std::mutex> lock(g_mutex);
  refused_commands().push_back(command ? command : "");
  return true;
}

}  // namespace

ProcessGuard::ProcessGuard() {
  std::lock_guard<std::mutex> lock(g_mutex);
  first_ = refused_commands().size();
  ++g_depth;
}

ProcessGuard::~ProcessGuard() {
  --g_depth;
}

std::vector<std::string> ProcessGuard::refused() const {
  std::lock_guard<std::mutex> lock(g_mutex);
  const auto& v = refused_commands();
  return std::vector<std::string>(v.begin() + static_cast<std::ptrdiff_t>(first_), v.end());
}

}  // namespace cvtmesh

// The interposed C library functions.
extern "C" int system(const char* command) {
  // system(NULL) only asks whether a shell exists (Gmsh asks before each SystemCall): answered.
  if (command && cvtmesh::refuse(command)) {
    errno = EPERM;
    return -1;
  }
  using Fn = int (*)(const char*);
  static const Fn real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "system"));
  if (!real) {
    errno = ENOSYS;
    return -1;
  }
  return real(command);
}

extern "C" FILE* popen(const char* command, const char* type) {
  if (cvtmesh::refuse(command)) {
    errno = EPERM;
    return nullptr;
  }
  using Fn = FILE* (*)(const char*, const char*);
  static const Fn real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "popen"));
  if (!real) {
    errno = ENOSYS;
    return nullptr;
  }
  return real(command, type);
}
