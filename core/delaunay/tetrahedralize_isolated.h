// TetGen's tetrahedralize run in a forked child process, so that a crash inside it (a
// segmentation fault on an input it mishandles, a corrupted memory pool) cannot take the
// optimizer down: the child (single-threaded: fork copies the calling thread only) runs TetGen on
// its copy of `in` and sends the output back through a pipe; the parent waits for it.
#pragma once
#include <string>
#include <vector>

class tetgenio;

namespace cvtmesh {

struct IsolatedTetgenOutput {
  std::vector<double> points;      // #P by 3 (the input's points first, then Steiner points)
  std::vector<int> tets;           // #T by 4 point ids (in.firstnumber base)
  std::vector<double> attributes;  // #T region attributes (switch A)
};

// Runs tetrahedralize(switches, &in, out) in a child. Throws InvariantError naming `stage` if
// TetGen throws an error code (tetgen_error's text), if the child dies by a signal ("TetGen
// died by signal 11 (Segmentation fault) in <stage>") or cannot be started, or if its output is
// cut short. When CVTMESH_TETGEN_IN_PROCESS is set in the environment, TetGen runs in this process
// (a debugging aid: no isolation); CVTMESH_TETGEN_CHILD_SIGNAL=N makes the child raise signal N
// instead of running TetGen (fault injection for the tests).
IsolatedTetgenOutput tetrahedralize_isolated(const char* switches, tetgenio& in,
                                             const std::string& stage);

}  // namespace cvtmesh
