// Per-mesh quality statistics: the columns of the paper's Tables 1-7.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/mesh/tri_mesh2.h"
#include "core/quality/quality.h"

namespace cvtmesh {

struct QualityStats {
  std::string label;
  int dim = 3;
  long nb_elements = 0;
  // Counts by the primary measure Q: 0.7<Q<=1, 0.5<Q<=0.7, 0.3<Q<=0.5, 0<Q<=0.3; and Q<=0.
  long bin[4] = {0, 0, 0, 0};
  long nb_inverted = 0;
  double q_min = 0, q_max = 0, q_avg = 0;
  double bad_pct = 0;    // Q < 0.3, percent of all elements
  double good_pct = 0;   // Q > 0.5, percent of all elements
  double min_angle = 0;  // degrees: dihedral (3D) or planar (2D)
  double max_angle = 0;
  double avg_radius_ratio = 0;
  // FE measures (core/quality/fe_measures.h), filled by the front ends that ask for them
  // (set_fe_measures); fe_measured false: not computed (the table shows "-", JSON null).
  bool fe_measured = false;
  double time_step = 0;            // global explicit time step, P1, lumped mass
  double element_time_step = 0;    // min over the elements of the element bound (<= time_step)
  long cg_iterations = 0;          // Jacobi-CG iterations, Poisson, boundary Dirichlet, 1e-8
  double stiffness_condition = 0;  // estimate of cond(D^-1 K) from the CG run
  // Extra rows (e.g. {"iterations", 42}, {"seconds", 1.3}), shown in insertion order.
  std::vector<std::pair<std::string, double>> extra;
};

// Per-element values of the primary measure Q (one per live element, in element order).
std::vector<double> element_qualities(const TetMesh& mesh, Measure m);
std::vector<double> element_qualities(const TriMesh2& mesh, Measure m);

// The tables' statistics of a mesh. For tets: one parallel pass without per-element arrays, the
// sums taken in fixed blocks of tets and the blocks in order: the same figures for any number of
// threads (the average may differ in the last bits from quality_stats_from_values's on the
// element_qualities, which sums in one sequence).
QualityStats quality_stats(const TetMesh& mesh, const std::string& label);
QualityStats quality_stats(const TriMesh2& mesh, const std::string& label);
// The rows of quality_stats that come from Q alone (counts, bins, Q min / max / average, bad and
// good percentages; the angles and the radius ratio left 0), without the angles' cost: what a
// progress report shows after every iteration. Its Q rows are quality_stats's, bit for bit.
QualityStats quality_summary(const TetMesh& mesh, const std::string& label);
QualityStats quality_summary(const TriMesh2& mesh, const std::string& label);
// The minimum of a measure over the live elements (+infinity without any); tets in parallel.
double min_quality(const TetMesh& mesh, Measure m);
double min_quality(const TriMesh2& mesh, Measure m);
// Statistics from precomputed per-element values (Q, radius ratio, min angle, max angle).
QualityStats quality_stats_from_values(const std::vector<double>& q, const std::vector<double>& rr,
                                       const std::vector<double>& min_angle,
                                       const std::vector<double>& max_angle, int dim,
                                       const std::string& label);

}  // namespace cvtmesh
