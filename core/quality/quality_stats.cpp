#include "core/quality/quality_stats.h"

#include <algorithm>
#include <array>
#include <limits>

namespace cvtmesh {
namespace {

// The counts of the quality table's Q rows: the four bins (0.7 < Q <= 1, 0.5 < Q <= 0.7,
// 0.3 < Q <= 0.5, 0 < Q <= 0.3), Q <= 0, bad (Q < 0.3) and good (Q > 0.5).
struct QCounts {
  long bin[4] = {0, 0, 0, 0};
  long inverted = 0, bad = 0, good = 0;
  void add(double v) {
    if (v > 0.7)
      ++bin[0];
    else if (v > 0.5)
      ++bin[1];
    else if (v > 0.3)
      ++bin[2];
    else if (v > 0)
      ++bin[3];
    else
      ++inverted;
    if (v < 0.3) ++bad;
    if (v > 0.5) ++good;
  }
  void add(const QCounts& o) {
    for (int k = 0; k < 4; ++k) bin[k] += o.bin[k];
    inverted += o.inverted;
    bad += o.bad;
    good += o.good;
  }
  void fill(QualityStats& s) const {
    for (int k = 0; k < 4; ++k) s.bin[k] = bin[k];
    s.nb_inverted = inverted;
    const double n = static_cast<double>(s.nb_elements);
    s.bad_pct = 100.0 * static_cast<double>(bad) / n;
    s.good_pct = 100.0 * static_cast<double>(good) / n;
  }
};

}  // namespace

std::vector<double> element_qualities(const TetMesh& mesh, Measure m) {
  // Per-tet slots filled in parallel, then the dead slots squeezed out in order: the same values
  // in the same order for any number of threads.
  const int nt = mesh.nb_tets();
  std::vector<double> q(nt);
  std::vector<char> live(nt);
#pragma omp parallel for schedule(static, 1024)
  for (int t = 0; t < nt; ++t) {
    const int* v = &mesh.tets[4 * static_cast<std::size_t>(t)];
    live[t] = v[0] >= 0;
    if (live[t])
      q[t] = tet_quality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]), m);
  }
  std::size_t n = 0;
  for (int t = 0; t < nt; ++t)
    if (live[t]) q[n++] = q[t];
  q.resize(n);
  return q;
}

std::vector<double> element_qualities(const TriMesh2& mesh, Measure m) {
  std::vector<double> q;
  q.reserve(mesh.nb_tris());
  for (int t = 0; t < mesh.nb_tris(); ++t) {
    const int* v = &mesh.tris[3 * t];
    if (v[0] < 0) continue;
    q.push_back(tri_quality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), 2, m));
  }
  return q;
}

QualityStats quality_stats_from_values(const std::vector<double>& q, const std::vector<double>& rr,
                                       const std::vector<double>& min_angle,
                                       const std::vector<double>& max_angle, int dim,
                                       const std::string& label) {
  QualityStats s;
  s.label = label;
  s.dim = dim;
  s.nb_elements = static_cast<long>(q.size());
  if (q.empty()) return s;
  double sum = 0, sum_rr = 0;
  QCounts counts;
  s.q_min = std::numeric_limits<double>::infinity();
  s.q_max = -std::numeric_limits<double>::infinity();
  for (double v : q) {
    sum += v;
    s.q_min = std::min(s.q_min, v);
    s.q_max = std::max(s.q_max, v);
    counts.add(v);
  }
  counts.fill(s);
  for (double v : rr) sum_rr += v;
  const double n = static_cast<double>(q.size());
  s.q_avg = sum / n;
  s.avg_radius_ratio = rr.empty() ? 0 : sum_rr / static_cast<double>(rr.size());
  s.min_angle = min_angle.empty() ? 0 : *std::min_element(min_angle.begin(), min_angle.end());
  s.max_angle = max_angle.empty() ? 0 : *std::max_element(max_angle.begin(), max_angle.end());
  return s;
}

QualityStats quality_stats(const TetMesh& mesh, const std::string& label) {
  // The four measures of each tet in one pass (in parallel), the dead slots squeezed out in
  // order: the same values as four element_qualities, for any number of threads.
  const int nt = mesh.nb_tets();
  std::vector<std::array<double, 4>> all(static_cast<std::size_t>(nt));
  std::vector<char> live(static_cast<std::size_t>(nt));
#pragma omp parallel for schedule(static, 1024)
  for (int t = 0; t < nt; ++t) {
    const int* v = &mesh.tets[4 * static_cast<std::size_t>(t)];
    live[t] = v[0] >= 0;
    if (live[t])
      all[t] = tet_table_qualities(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]),
                                   mesh.point(v[3]));
  }
  std::vector<double> m[4];
  for (auto& x : m) x.reserve(static_cast<std::size_t>(nt));
  for (int t = 0; t < nt; ++t)
    if (live[t])
      for (int k = 0; k < 4; ++k) m[k].push_back(all[t][k]);
  return quality_stats_from_values(m[0], m[1], m[2], m[3], 3, label);
}

QualityStats quality_summary(const TetMesh& mesh, const std::string& label) {
  const int nt = mesh.nb_tets();
  constexpr int kBlock = 4096;
  const int nb = (nt + kBlock - 1) / kBlock;
  struct Part {
    double sum = 0, lo = std::numeric_limits<double>::infinity(),
           hi = -std::numeric_limits<double>::infinity();
    long n = 0;
    QCounts counts;
  };
  std::vector<Part> parts(static_cast<std::size_t>(nb));
#pragma omp parallel for schedule(static, 4)
  for (int b = 0; b < nb; ++b) {
    Part& p = parts[b];
    const int end = std::min(nt, (b + 1) * kBlock);
    for (int t = b * kBlock; t < end; ++t) {
      const int* v = &mesh.tets[4 * static_cast<std::size_t>(t)];
      if (v[0] < 0) continue;
      const double q = tet_quality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]),
                                   mesh.point(v[3]), Measure::kQ);
      ++p.n;
      p.sum += q;
      p.lo = std::min(p.lo, q);
      p.hi = std::max(p.hi, q);
      p.counts.add(q);
    }
  }
  QualityStats s;
  s.label = label;
  s.dim = 3;
  Part all;
  for (const Part& p : parts) {
    all.n += p.n;
    all.sum += p.sum;
    all.lo = std::min(all.lo, p.lo);
    all.hi = std::max(all.hi, p.hi);
    all.counts.add(p.counts);
  }
  s.nb_elements = all.n;
  if (all.n == 0) return s;
  const double n = static_cast<double>(all.n);
  s.q_min = all.lo;
  s.q_max = all.hi;
  s.q_avg = all.sum / n;
  all.counts.fill(s);
  return s;
}

QualityStats quality_stats(const TriMesh2& mesh, const std::string& label) {
  return quality_stats_from_values(element_qualities(mesh, Measure::kQ),
                                   element_qualities(mesh, Measure::kRadiusRatio),
                                   element_qualities(mesh, Measure::kMinAngle),
                                   element_qualities(mesh, Measure::kMaxAngle), 2, label);
}

}  // namespace cvtmesh
