#include "bench/baselines/netgen_optimize.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench/baselines/verify_peer.h"
#include "core/util/error.h"

#ifndef CVTMESH_SOURCE_DIR
#define CVTMESH_SOURCE_DIR "."
#endif

namespace cvtmesh {

namespace {

template <class T>
void put(std::ofstream& f, const std::vector<T>& v) {
  f.write(reinterpret_cast<const char*>(v.data()),
          static_cast<std::streamsize>(v.size() * sizeof(T)));
}

template <class T>
void get(std::ifstream& f, std::vector<T>& v, std::int64_t n) {
  v.resize(static_cast<std::size_t>(n));
  f.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
}

void write_input(const TetMesh& m, const std::string& path) {
  std::vector<int> tets, region;
  for (int t = 0; t < m.nb_tets(); ++t)
    if (m.tets[4 * t] >= 0) {
      tets.insert(tets.end(), &m.tets[4 * t], &m.tets[4 * t] + 4);
      region.push_back(m.tet_region[t]);
    }
  std::ofstream f(path, std::ios::binary);
  const std::vector<std::int64_t> n = {m.nb_vertices(), static_cast<std::int64_t>(region.size()),
                                       m.nb_tris()};
  put(f, n);
  put(f, m.xyz);
  put(f, tets);
  put(f, region);
  put(f, m.tris);
  put(f, m.tri_surface);
  if (!f) throw OutputError("netgen baseline: cannot write '" + path + "'");
}

// Runs python3 SCRIPT IN OUT; returns its exit code (-1: killed by a signal).
int run_script(const std::string& in, const std::string& out) {
  const char* py = std::getenv("CVTMESH_PYTHON");
  const std::string python = py ? py : "/usr/bin/python3";
  const std::string script = netgen_script_path();
  const bool verbose = std::getenv("CVTMESH_NETGEN_VERBOSE") != nullptr;
  const pid_t pid = fork();
  if (pid < 0) throw InvariantError("netgen baseline: fork failed");
  if (pid == 0) {
    if (!verbose) {
      const int null = open("/dev/null", O_WRONLY);
      if (null >= 0) {
        dup2(null, 1);
        dup2(null, 2);
      }
    }
    execl(python.c_str(), python.c_str(), script.c_str(), in.c_str(), out.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  if (!WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

}  // namespace

std::string netgen_script_path() {
  if (const char* s = std::getenv("CVTMESH_NETGEN_SCRIPT")) return s;
  return std::string(CVTMESH_SOURCE_DIR) + "/bench/baselines/netgen_optimize.py";
}

NetgenResult netgen_optimize(TetMesh& m) {
  NetgenResult r;
  std::string tmpl = (std::filesystem::temp_directory_path() / "cvtmesh-netgen-XXXXXX").string();
  if (!mkdtemp(tmpl.data())) throw OutputError("netgen baseline: cannot create a temp directory");
  const std::string dir = tmpl, in = dir + "/in.bin", out = dir + "/out.bin";
  struct Cleanup {
    std::string d;
    ~Cleanup() {
      std::error_code ec;
      std::filesystem::remove_all(d, ec);
    }
  } cleanup{dir};
  write_input(m, in);
  const int code = run_script(in, out);
  if (code == 3 || code == 127) {
    r.message = code == 3 ? "python3-netgen is not installed" : "no /usr/bin/python3";
    return r;
  }
  if (code != 0)
    throw InvariantError(code < 0 ? "Netgen's optimizer crashed"
                                  : "Netgen's optimizer failed (exit " + std::to_string(code) +
                                        "; CVTMESH_NETGEN_VERBOSE=1 shows its output)");
  std::ifstream f(out, std::ios::binary);
  std::vector<double> seconds;
  std::vector<std::int64_t> n;
  get(f, seconds, 1);
  get(f, n, 3);
  TetMesh after;
  get(f, after.xyz, 3 * n[0]);
  get(f, after.tets, 4 * n[1]);
  get(f, after.tet_region, n[1]);
  get(f, after.tris, 3 * n[2]);
  get(f, after.tri_surface, n[2]);
  if (!f) throw InvariantError("netgen baseline: truncated result from the script");
  classify_peer_vertices(m, after);
  verify_peer(m, after, "Netgen");
  m = std::move(after);
  r.available = true;
  r.seconds = seconds[0];
  return r;
}

}  // namespace cvtmesh
