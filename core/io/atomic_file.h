// Atomic output: write to a temporary file in the target directory, fsync, rename over the
// target. A failure (or an exception before commit) removes the temporary: no half-written file.
#pragma once
#include <string>
#include <vector>

namespace cvtmesh {

class AtomicFile {
 public:
  // target: the final path. The temporary keeps the target's extension (Gmsh picks formats by
  // extension). Throws OutputError if the directory does not exist or is not writable.
  explicit AtomicFile(const std::string& target);
  ~AtomicFile();  // removes the temporary unless committed
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& temp_path() const { return temp_; }
  const std::string& target() const { return target_; }
  // Checks that the file system still accepts data (a full disk or the file size limit would
  // have truncated the temporary: OutputError), fsyncs the temporary and renames it to the
  // target. Throws OutputError.
  void commit();

 private:
  std::string target_, temp_;
  bool committed_ = false;
};

// Removes every temporary not yet committed and makes later commits fail (OutputError): what a
// front end calls before it stops the process early (the CLI's --time-limit), so that no partial
// output is left. Thread-safe; a commit is either complete before it or never happens.
void abandon_pending_outputs();

// Options shared by every writer.
struct OutputPolicy {
  bool force = false;      // allow replacing an existing output file
  std::string input_path;  // refuse to write over this file unless in_place
  bool in_place = false;
};

// Throws OutputError if writing `target` would violate the policy (existing file without force,
// the input itself without in_place, a directory, a missing directory).
void check_output_allowed(const std::string& target, const OutputPolicy& policy);

// Throws OutputError if the directory of `target` does not exist or is not writable (what
// AtomicFile's constructor checks).
void check_directory_writable(const std::string& target);

// True if both paths name the same existing file (same device and inode).
bool same_file(const std::string& a, const std::string& b);

}  // namespace cvtmesh
