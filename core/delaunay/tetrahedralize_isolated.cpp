#include "core/delaunay/tetrahedralize_isolated.h"

#include <sys/wait.h>
#include <tetgen.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/delaunay/tetgen_error.h"
#include "core/geometry/tetgen_library.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

// The child's message: a header, then the three arrays.
struct Header {
  int status = 0;  // 0: done; 1: TetGen threw `code`
  int code = 0;
  long long nb_points = 0, nb_tets = 0;
};

bool write_all(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

IsolatedTetgenOutput copy_output(const tetgenio& out) {
  IsolatedTetgenOutput r;
  r.points.assign(out.pointlist, out.pointlist + 3 * static_cast<std::size_t>(out.numberofpoints));
  r.tets.assign(out.tetrahedronlist,
                out.tetrahedronlist + 4 * static_cast<std::size_t>(out.numberoftetrahedra));
  if (out.tetrahedronattributelist)
    r.attributes.assign(out.tetrahedronattributelist,
                        out.tetrahedronattributelist + out.numberoftetrahedra);
  return r;
}

[[noreturn]] void child(int fd, const char* switches, tetgenio& in) {
  Header h;
  tetgenio out;
  std::vector<char> sw(switches, switches + std::strlen(switches) + 1);
  // Fault injection for the tests: the child dies by this signal instead of running TetGen.
  if (const char* sig = std::getenv("CVTMESH_TETGEN_CHILD_SIGNAL")) std::raise(std::atoi(sig));
  try {
    tetgen_library().tetrahedralize(sw.data(), &in, &out, nullptr, nullptr);
  } catch (int code) {
    h.status = 1;
    h.code = code;
  } catch (...) {
    h.status = 1;
    h.code = -1;
  }
  bool ok = true;
  if (h.status == 0) {
    h.nb_points = out.numberofpoints;
    h.nb_tets = out.numberoftetrahedra;
    ok = write_all(fd, &h, sizeof h) &&
         write_all(fd, out.pointlist, sizeof(double) * 3 * static_cast<std::size_t>(h.nb_points)) &&
         write_all(fd, out.tetrahedronlist, sizeof(int) * 4 * static_cast<std::size_t>(h.nb_tets));
    for (long long t = 0; ok && t < h.nb_tets; ++t) {
      const double a = out.tetrahedronattributelist ? out.tetrahedronattributelist[t] : 0.0;
      ok = write_all(fd, &a, sizeof a);
    }
  } else {
    ok = write_all(fd, &h, sizeof h);
  }
  ::close(fd);
  // No destructors, no atexit handlers (the parent's state lives on there).
  ::_exit(ok ? 0 : 3);
}

std::string signal_name(int sig) {
  const char* d = strsignal(sig);
  return "signal " + std::to_string(sig) + (d ? " (" + std::string(d) + ")" : "");
}

}  // namespace

IsolatedTetgenOutput tetrahedralize_isolated(const char* switches, tetgenio& in,
                                             const std::string& stage) {
  const TetgenLibrary& lib = tetgen_library();  // loaded here, before the fork
  if (std::getenv("CVTMESH_TETGEN_IN_PROCESS")) {
    tetgenio out;
    std::vector<char> sw(switches, switches + std::strlen(switches) + 1);
    try {
      lib.tetrahedralize(sw.data(), &in, &out, nullptr, nullptr);
    } catch (int code) {
      throw InvariantError("TetGen failed in " + stage + ": " + tetgen_error(code));
    }
    return copy_output(out);
  }
  int fds[2];
  if (::pipe(fds) != 0)
    throw InvariantError("cannot start TetGen for " + stage + ": pipe: " + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw InvariantError("cannot start TetGen for " + stage + ": fork: " + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(fds[0]);
    child(fds[1], switches, in);
  }
  ::close(fds[1]);
  // Read everything (the child blocks on a full pipe until we do), then reap it.
  std::vector<char> buf;
  char chunk[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fds[0], chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    buf.insert(buf.end(), chunk, chunk + n);
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status))
    throw InvariantError("TetGen died by " + signal_name(WTERMSIG(status)) + " in " + stage +
                         " (run in a child process: the optimizer goes on without it)");
  Header h;
  if (buf.size() < sizeof h)
    throw InvariantError("TetGen's child process for " + stage + " ended without a result (exit " +
                         std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
  std::memcpy(&h, buf.data(), sizeof h);
  if (h.status != 0)
    throw InvariantError("TetGen failed in " + stage + ": " + tetgen_error(h.code));
  const std::size_t need = sizeof h + sizeof(double) * 3 * static_cast<std::size_t>(h.nb_points) +
                           sizeof(int) * 4 * static_cast<std::size_t>(h.nb_tets) +
                           sizeof(double) * static_cast<std::size_t>(h.nb_tets);
  if (h.nb_points < 0 || h.nb_tets < 0 || buf.size() != need)
    throw InvariantError("TetGen's child process for " + stage + " sent a cut-short result");
  IsolatedTetgenOutput r;
  const char* p = buf.data() + sizeof h;
  r.points.resize(3 * static_cast<std::size_t>(h.nb_points));
  std::memcpy(r.points.data(), p, sizeof(double) * r.points.size());
  p += sizeof(double) * r.points.size();
  r.tets.resize(4 * static_cast<std::size_t>(h.nb_tets));
  std::memcpy(r.tets.data(), p, sizeof(int) * r.tets.size());
  p += sizeof(int) * r.tets.size();
  r.attributes.resize(static_cast<std::size_t>(h.nb_tets));
  std::memcpy(r.attributes.data(), p, sizeof(double) * r.attributes.size());
  return r;
}

}  // namespace cvtmesh
