#include "convert/progress_display.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>

#include "convert/cli_common.h"

namespace cvtmesh::cli {
namespace {

double seconds_between(std::chrono::steady_clock::time_point a,
                       std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

std::string duration_text(double s) {
  char buf[32];
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.1f s", s);
  else
    std::snprintf(buf, sizeof buf, "%d min %02d s", static_cast<int>(s / 60),
                  static_cast<int>(s) % 60);
  return buf;
}

// The name a person reads for a phase of the core.
std::string phase_name(const std::string& phase) {
  if (phase == "smooth") return "polish";
  if (phase == "bnd-cvt") return "boundary";
  return phase;
}

bool lloyd_like(const OptimizeProgress& p) {
  return p.max_iterations > 0;
}

}  // namespace

double lloyd_eta(const std::vector<std::pair<double, double>>& h, int iteration, int max_iterations,
                 double tolerance) {
  if (h.size() < 3 || iteration <= 0) return -1;
  const double per_iteration = h.back().first / static_cast<double>(h.size());
  int left = std::max(0, max_iterations - iteration);
  const std::size_t window = std::min<std::size_t>(h.size() - 1, 10);
  const double fall = (h[h.size() - 1 - window].second - h.back().second) / window;
  if (tolerance > 0 && fall > 0 && std::isfinite(h.back().second)) {
    const double need = (h.back().second - std::log10(tolerance)) / fall;
    if (need >= 0) left = std::min(left, static_cast<int>(std::ceil(need)));
  }
  return left * per_iteration;
}

ProgressDisplay::ProgressDisplay(Mode mode, bool verbose, std::FILE* out)
    : mode_(mode), verbose_(verbose && mode != Mode::kQuiet), out_(out) {}

ProgressDisplay ProgressDisplay::for_stderr() {
  const GlobalOpts& g = global_opts();
  Mode m = isatty(fileno(stderr)) ? Mode::kTerminal : Mode::kPlain;
  if (const char* e = std::getenv("CVTMESH_PROGRESS")) {
    if (std::strcmp(e, "plain") == 0) m = Mode::kPlain;
    if (std::strcmp(e, "terminal") == 0) m = Mode::kTerminal;
  }
  if (g.quiet) m = Mode::kQuiet;
  ProgressDisplay d(m, g.verbose);
  if (const char* e = std::getenv("CVTMESH_PROGRESS_INTERVAL")) {
    char* end = nullptr;
    const double s = std::strtod(e, &end);
    if (end != e && s >= 0 && s <= 60) d.min_interval_ = s;
  }
  return d;
}

void ProgressDisplay::begin(const std::string& phase, const std::string& detail) {
  finish();
  if (mode_ == Mode::kQuiet) return;
  phase_ = phase;
  detail_ = detail;
  start_ = std::chrono::steady_clock::now();
  history_.clear();
  has_last_ = false;
  show(true);
}

void ProgressDisplay::flush_pending() {
  std::fputs(pending_.c_str(), out_);
  std::fflush(out_);
  pending_.clear();
}

void ProgressDisplay::done() {
  finish();
  core_started_ = true;
  if (!pending_.empty()) flush_pending();
}

void ProgressDisplay::update(const OptimizeProgress& p) {
  if (mode_ == Mode::kQuiet) return;
  if (!core_started_) {
    core_started_ = true;
    if (!pending_.empty()) flush_pending();
  }
  const std::string name = phase_name(p.phase);
  if (name != phase_) begin(name, "");
  if (p.start) return;
  last_ = p;
  has_last_ = true;
  if (lloyd_like(p))
    history_.push_back({seconds_between(start_, std::chrono::steady_clock::now()),
                        p.D > 0 ? std::log10(p.D) : -300.0});
  if (verbose_) {
    // Today's detail: every report on its own line, with the Lloyd internals.
    std::string l = line();
    if (p.nb_dual_cells + p.nb_clipped_cells > 0) {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "  [cells %.2fs (%d dual, %d clipped), Delaunay %.2fs (%s%d flips",
                    p.seconds_cells, p.nb_dual_cells, p.nb_clipped_cells, p.seconds_delaunay,
                    p.rebuilt ? "rebuilt, " : "", p.nb_flips);
      l += buf;
      if (p.nb_stuck_faces + p.nb_short_moves > 0) {
        std::snprintf(buf, sizeof buf, ", %d faces not Delaunay, %d moves short", p.nb_stuck_faces,
                      p.nb_short_moves);
        l += buf;
      }
      std::snprintf(buf, sizeof buf, "), %.2fs]", p.seconds_other);
      l += buf;
    }
    std::fprintf(out_, "%s\n", l.c_str());
    std::fflush(out_);
    return;
  }
  show(false);
}

std::string ProgressDisplay::line() const {
  char buf[320];
  std::string l = phase_;
  l.resize(std::max<std::size_t>(l.size(), 9), ' ');
  if (!detail_.empty()) l += " " + detail_;
  if (!has_last_) return l + (mode_ == Mode::kTerminal ? " ..." : "");
  const OptimizeProgress& p = last_;
  if (lloyd_like(p)) {
    std::snprintf(buf, sizeof buf, " it %d/%d%s  D %.2e (tol %.0e)  energy %.6e", p.iteration,
                  p.max_iterations, p.restarted ? "*" : "", p.D, p.tolerance, p.energy);
    l += buf;
  } else {
    std::snprintf(buf, sizeof buf, " %s %d", p.phase == "swap" ? "passes" : "it", p.iteration);
    l += buf;
    if (p.energy != 0) {
      std::snprintf(buf, sizeof buf, "  energy %.6e", p.energy);
      l += buf;
    }
  }
  if (p.q_avg > 0) {
    std::snprintf(buf, sizeof buf, "  Q_min %.4f  Q_avg %.4f", p.q_min, p.q_avg);
    l += buf;
  }
  if (lloyd_like(p) && mode_ == Mode::kTerminal && !verbose_ && !phase_ended_) {
    const double eta = lloyd_eta(history_, p.iteration, p.max_iterations, p.tolerance);
    if (eta >= 0) l += "  ETA " + duration_text(eta);
  }
  return l;
}

void ProgressDisplay::show(bool force) {
  if (mode_ != Mode::kTerminal || verbose_) return;
  const auto now = std::chrono::steady_clock::now();
  if (!force && drawn_ && seconds_between(last_draw_, now) < min_interval_) return;  // 10 per s
  last_draw_ = now;
  std::string l = line();
  winsize ws{};
  if (ioctl(fileno(out_), TIOCGWINSZ, &ws) == 0 && ws.ws_col > 1 && l.size() >= ws.ws_col)
    l.resize(ws.ws_col - 1);  // a wrapped line cannot be redrawn in place
  std::fprintf(out_, "\r\033[K%s", l.c_str());
  std::fflush(out_);
  drawn_ = true;
}

void ProgressDisplay::finish() {
  if (phase_.empty() || mode_ == Mode::kQuiet) return;
  const double s = seconds_between(start_, std::chrono::steady_clock::now());
  if (std::uncaught_exceptions() > 0) {
    // Unwinding: an error ends the run, and its message is the one line on stderr (docs/cli.md).
    if (drawn_) std::fprintf(out_, "\r\033[K");
    std::fflush(out_);
    drawn_ = false;
    phase_.clear();
    return;
  }
  if (!verbose_) {
    phase_ended_ = true;  // the kept line has no ETA
    std::string l = line();
    phase_ended_ = false;
    if (mode_ == Mode::kTerminal && !has_last_) l.resize(l.size() - 4);  // drop " ..."
    l += "  (" + duration_text(s) + ")";
    if (mode_ == Mode::kTerminal) {
      std::fprintf(out_, "\r\033[K%s\n", l.c_str());
    } else {
      // Plain lines wait until the core has started: a run refused before (a bad input, an
      // output that cannot be written) prints its error alone, one line (docs/cli.md).
      pending_ += l + "\n";
      if (core_started_) flush_pending();
    }
    std::fflush(out_);
  }
  drawn_ = false;
  phase_.clear();
}

}  // namespace cvtmesh::cli
