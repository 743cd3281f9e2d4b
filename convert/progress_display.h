// The CLI's progress on stderr: the one place it is drawn (the core reports through the
// OptimizeOptions::progress callback and never prints). One line per phase: reading or meshing
// the input, Lloyd (iteration / cap, D against the tolerance, an ETA), SWAP, the polish, the
// checks, writing.
//   terminal (stderr is a TTY): the phase's line is redrawn in place ("\r" + clear to the end of
//                               the line) as it progresses, and kept with its time when it ends;
//   plain (a file or a pipe):   one line per phase when it ends (held until the core reports, so
//                               that a run refused before prints only its error);
//   verbose (-v):               every report on a line of its own, with the Lloyd internals;
//   quiet (-q):                 nothing.
#pragma once
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "core/pipeline/optimize.h"

namespace cvtmesh::cli {

class ProgressDisplay {
 public:
  enum class Mode { kQuiet, kPlain, kTerminal };
  ProgressDisplay(Mode mode, bool verbose, std::FILE* out = stderr);
  // The mode of the global options (-q, -v) and of stderr (isatty). CVTMESH_PROGRESS=plain or
  // =terminal forces one (tests, CI logs).
  static ProgressDisplay for_stderr();
  ~ProgressDisplay() { finish(); }
  ProgressDisplay(const ProgressDisplay&) = delete;
  ProgressDisplay& operator=(const ProgressDisplay&) = delete;
  ProgressDisplay(ProgressDisplay&&) = default;

  // A phase of the front end begins ("reading", "meshing", "writing"; detail: the file).
  void begin(const std::string& phase, const std::string& detail);
  // A report of the core (the callback of OptimizeOptions::progress).
  void update(const OptimizeProgress& p);
  // Ends the current phase's line (its last state and its time).
  void finish();
  // The run has succeeded: ends the current phase and prints the lines still held.
  void done();
  // -q: nothing is drawn (the caller need not report).
  bool quiet() const { return mode_ == Mode::kQuiet; }

 private:
  void show(bool force);
  void flush_pending();
  std::string line() const;

  Mode mode_;
  bool verbose_;
  std::FILE* out_;
  std::string phase_, detail_;  // current phase ("" = none) and its text
  bool drawn_ = false;          // terminal: a line is on screen, not ended
  double min_interval_ = 0.1;   // terminal: seconds between redraws (CVTMESH_PROGRESS_INTERVAL)
  std::chrono::steady_clock::time_point start_, last_draw_;
  // Lloyd: (seconds since the phase began, log10 D) of the iterations, for the ETA.
  std::vector<std::pair<double, double>> history_;
  OptimizeProgress last_;
  bool has_last_ = false;
  bool phase_ended_ = false;   // finish() is drawing the line that stays
  bool core_started_ = false;  // the core has reported (plain lines are no longer held)
  std::string pending_;        // plain: finished lines held until the core has started
};

// The ETA of a Lloyd-type phase, in seconds (negative: unknown): the iterations left until D
// reaches the tolerance, at the rate log D fell over the last iterations (at most the cap),
// times the mean time of an iteration. history: (seconds since the phase began, log10 D).
double lloyd_eta(const std::vector<std::pair<double, double>>& history, int iteration,
                 int max_iterations, double tolerance);

}  // namespace cvtmesh::cli
