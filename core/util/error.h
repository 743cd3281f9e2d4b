// Typed errors thrown by core/ for bad input or a failed invariant. core/ never prints or exits.
#pragma once
#include <stdexcept>
#include <string>

namespace cvtmesh {

// Input a user can fix: unreadable/corrupt file, unsupported element type, empty mesh, ...
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Output could not be written (permissions, disk full, refusing to overwrite).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A mesh invariant was violated by an operation: always a bug, never silently ignored.
class InvariantError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

}  // namespace cvtmesh
