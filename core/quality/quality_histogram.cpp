#include "core/quality/quality_histogram.h"

#include <algorithm>
#include <stdexcept>

namespace cvtmesh {

QualityHistogram quality_histogram(const std::vector<double>& q, int bins,
                                   const std::string& label) {
  if (bins < 1) throw std::invalid_argument("quality_histogram: bins must be >= 1");
  QualityHistogram h;
  h.label = label;
  h.nb_elements = static_cast<int>(q.size());
  h.fraction.assign(bins, 0.0);
  if (q.empty()) return h;
  std::vector<long> count(bins, 0);
  double sum = 0;
  h.q_min = q.front();
  for (double v : q) {
    sum += v;
    h.q_min = std::min(h.q_min, v);
    if (v <= 0) ++h.nb_inverted;
    const int b = std::clamp(static_cast<int>(v * bins), 0, bins - 1);
    ++count[b];
  }
  for (int b = 0; b < bins; ++b)
    h.fraction[b] = static_cast<double>(count[b]) / static_cast<double>(q.size());
  h.q_avg = sum / static_cast<double>(q.size());
  return h;
}

}  // namespace cvtmesh
