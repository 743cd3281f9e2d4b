#include "convert/limits.h"

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <thread>

#include "core/io/atomic_file.h"

namespace cvtmesh::cli {
namespace {

// The deadline of --time-limit (steady clock), if any.
bool g_has_deadline = false;
std::chrono::steady_clock::time_point g_deadline;

}  // namespace

double seconds_left() {
  if (!g_has_deadline) return std::numeric_limits<double>::infinity();
  return std::chrono::duration<double>(g_deadline - std::chrono::steady_clock::now()).count();
}

void add_limit_options(CLI::App& app, Limits& limits) {
  app.add_option("--max-memory", limits.max_memory_mb,
                 "refuse to use more than this many MB of address space (exit 2 when reached)")
      ->check(CLI::PositiveNumber);
  app.add_option("--time-limit", limits.time_limit_s,
                 "stop after this many seconds of wall time (exit 2, no output written)")
      ->check(CLI::PositiveNumber);
}

void apply_limits(const Limits& limits) {
  if (limits.max_memory_mb > 0) {
    rlimit r{};
    getrlimit(RLIMIT_AS, &r);
    const double bytes = limits.max_memory_mb * 1024.0 * 1024.0;
    r.rlim_cur = static_cast<rlim_t>(std::min(bytes, 1.0e18));
    if (r.rlim_max != RLIM_INFINITY && r.rlim_cur > r.rlim_max) r.rlim_cur = r.rlim_max;
    if (setrlimit(RLIMIT_AS, &r) != 0)
      throw CLI::ValidationError("--max-memory", "cannot set the address-space limit");
  }
  if (limits.time_limit_s > 0) {
    const double s = limits.time_limit_s;
    g_has_deadline = true;
    g_deadline = std::chrono::steady_clock::now() +
                 std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                     std::chrono::duration<double>(s));
    std::thread([s] {
      std::this_thread::sleep_for(std::chrono::duration<double>(s));
      abandon_pending_outputs();
      char msg[160];
      const int n = std::snprintf(msg, sizeof msg,
                                  "cvtmesh: error: time limit of %g s reached (--time-limit); no "
                                  "output written\n",
                                  s);
      if (n > 0) (void)!::write(2, msg, static_cast<std::size_t>(n));
      _exit(2);
    }).detach();
  }
}

}  // namespace cvtmesh::cli
