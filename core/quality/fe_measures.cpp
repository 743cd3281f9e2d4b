#include "core/quality/fe_measures.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/quality/explicit_time_step.h"
#include "core/quality/poisson_cg.h"

namespace cvtmesh {
namespace {

template <class Mesh>
FeMeasures measure(const Mesh& mesh, const FeOptions& o, long nb_elements) {
  if (o.mode != "auto" && o.mode != "on" && o.mode != "off")
    throw std::invalid_argument("FE measures: mode '" + o.mode + "' (expected auto, on or off)");
  if (!(o.wave_speed > 0) || !std::isfinite(o.wave_speed))
    throw std::invalid_argument("FE measures: the wave speed must be positive");
  FeMeasures m;
  if (o.mode == "off") {
    m.skipped = "off";
    return m;
  }
  if (o.mode == "auto" && nb_elements > kFeMeasuresAutoLimit) {
    m.skipped = std::to_string(nb_elements) + " elements > " +
                std::to_string(kFeMeasuresAutoLimit) + " (force with --fe-measures on)";
    return m;
  }
  if (nb_elements == 0) {
    m.skipped = "no elements";
    return m;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const P1System sys = p1_system(mesh);
  const ExplicitTimeStep ts = explicit_time_step(sys, o.eigen_tolerance);
  const PoissonCg cg = poisson_cg(sys, o.cg_tolerance);
  const double dt_e = min_quality(mesh, Measure::kTimeStep);
  m.measured = true;
  m.time_step = ts.time_step / o.wave_speed;
  m.element_time_step = dt_e / o.wave_speed;
  m.cg_iterations = cg.iterations;
  m.stiffness_condition = cg.condition;
  m.lanczos_iterations = ts.iterations;
  m.converged = ts.converged && cg.converged;
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return m;
}

}  // namespace

FeMeasures fe_measures(const TetMesh& mesh, const FeOptions& options) {
  long n = 0;
  for (int t = 0; t < mesh.nb_tets(); ++t) n += mesh.tets[4 * static_cast<std::size_t>(t)] >= 0;
  return measure(mesh, options, n);
}

FeMeasures fe_measures(const TriMesh2& mesh, const FeOptions& options) {
  long n = 0;
  for (int t = 0; t < mesh.nb_tris(); ++t) n += mesh.tris[3 * static_cast<std::size_t>(t)] >= 0;
  return measure(mesh, options, n);
}

void set_fe_measures(QualityStats& s, const FeMeasures& m) {
  s.fe_measured = m.measured;
  s.time_step = m.time_step;
  s.element_time_step = m.element_time_step;
  s.cg_iterations = m.cg_iterations;
  s.stiffness_condition = m.stiffness_condition;
}

}  // namespace cvtmesh
