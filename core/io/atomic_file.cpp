#include "core/io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <random>
#include <set>

#include "core/util/error.h"

namespace cvtmesh {
namespace fs = std::filesystem;

namespace {
// The temporaries not yet committed or removed, for abandon_pending_outputs().
std::mutex g_pending_mutex;
std::set<std::string> g_pending;
bool g_abandoned = false;

std::string dir_of(const std::string& path) {
  const fs::path p(path);
  return p.has_parent_path() ? p.parent_path().string() : std::string(".");
}
}  // namespace

void check_directory_writable(const std::string& target) {
  const std::string dir = dir_of(target);
  struct stat st;
  if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw OutputError("cannot write '" + target + "': directory '" + dir + "' does not exist");
  if (access(dir.c_str(), W_OK) != 0)
    throw OutputError("cannot write '" + target + "': directory '" + dir + "' is not writable");
}

AtomicFile::AtomicFile(const std::string& target) : target_(target) {
  check_directory_writable(target);
  const std::string dir = dir_of(target);
  const fs::path p(target);
  std::random_device rd;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%08x", rd());
  temp_ =
      (fs::path(dir) / ("." + p.stem().string() + ".cvtmesh-tmp-" + buf + p.extension().string()))
          .string();
  std::lock_guard<std::mutex> lock(g_pending_mutex);
  g_pending.insert(temp_);
}

AtomicFile::~AtomicFile() {
  std::lock_guard<std::mutex> lock(g_pending_mutex);
  if (!committed_) std::remove(temp_.c_str());
  g_pending.erase(temp_);
}

void abandon_pending_outputs() {
  std::lock_guard<std::mutex> lock(g_pending_mutex);
  g_abandoned = true;
  for (const std::string& t : g_pending) std::remove(t.c_str());
  g_pending.clear();
}

void AtomicFile::commit() {
  const int fd = ::open(temp_.c_str(), O_WRONLY | O_APPEND);
  if (fd < 0)
    throw OutputError("cannot write '" + target_ + "': the temporary output was not created (" +
                      std::strerror(errno) + ")");
  // Gmsh's and OpenMesh's writers ignore write errors: on a full disk or past the file size limit
  // they leave a truncated file and report success. Both conditions persist, so one more byte
  // appended now fails too (it is removed again when it does not).
  struct stat st;
  if (::fstat(fd, &st) == 0) {
    const char probe = '\n';
    if (::write(fd, &probe, 1) != 1) {
      const int err = errno;
      ::close(fd);
      throw OutputError("cannot write '" + target_ + "': " + std::strerror(err) +
                        " (the output is incomplete)");
    }
    if (::ftruncate(fd, st.st_size) != 0) {
      const int err = errno;
      ::close(fd);
      throw OutputError("cannot write '" + target_ + "': " + std::strerror(err));
    }
  }
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0)
    throw OutputError("cannot write '" + target_ + "': " + std::strerror(err) +
                      " (disk full or I/O error?)");
  std::lock_guard<std::mutex> lock(g_pending_mutex);
  if (g_abandoned) throw OutputError("cannot write '" + target_ + "': the run was stopped");
  if (std::rename(temp_.c_str(), target_.c_str()) != 0)
    throw OutputError("cannot write '" + target_ + "': " + std::strerror(errno));
  committed_ = true;
  // Persist the rename itself.
  const int dfd = ::open(dir_of(target_).c_str(), O_RDONLY | O_DIRECTORY);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa, sb;
  if (stat(a.c_str(), &sa) != 0 || stat(b.c_str(), &sb) != 0) return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

void check_output_allowed(const std::string& target, const OutputPolicy& policy) {
  struct stat st;
  if (stat(target.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw OutputError("cannot write '" + target + "': it is a directory");
    if (!policy.input_path.empty() && same_file(target, policy.input_path) && !policy.in_place)
      throw OutputError("refusing to overwrite the input file '" + target +
                        "' (use --in-place to replace it)");
    if (!policy.force && !(policy.in_place && same_file(target, policy.input_path)))
      throw OutputError("output file '" + target + "' exists (use --force to replace it)");
  }
}

}  // namespace cvtmesh
