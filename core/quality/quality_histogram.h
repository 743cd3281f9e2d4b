// The quality histogram of a mesh (a pure function): the fraction of elements per bin of Q over
// [0, 1], as Gmsh's Statistics window and the paper's four-bin tables show it.
#pragma once
#include <string>
#include <vector>

namespace cvtmesh {

struct QualityHistogram {
  std::string label;
  int nb_elements = 0;
  int nb_inverted = 0;           // Q <= 0 (counted in the first bin too)
  std::vector<double> fraction;  // per bin, summing to 1 (empty mesh: all 0)
  double q_min = 0, q_avg = 0;
};

// `bins` equal bins over [0, 1]; a value of exactly 1 goes in the last bin, Q <= 0 in the first.
QualityHistogram quality_histogram(const std::vector<double>& q, int bins,
                                   const std::string& label);

}  // namespace cvtmesh
