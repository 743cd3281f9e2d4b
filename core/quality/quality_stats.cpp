#include "core/quality/quality_stats.h"

#include "core/mesh/check_surface_mesh.h"

#include <algorithm>
#include <array>
#include <limits>

#include "core/mesh/kept_quads.h"
#include "core/quality/quad_angles.h"
#include "core/quality/quad_scaled_jacobian.h"

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

namespace {

// A surface mesh in space (a TetMesh without tets: check_surface_mesh.h): its elements are its
// triangles, measured in 3D.
std::vector<double> surface_qualities(const TetMesh& mesh, Measure m) {
  std::vector<double> q;
  q.reserve(mesh.nb_tris());
  for (int f = 0; f < mesh.nb_tris(); ++f) {
    const int* v = &mesh.tris[3 * f];
    if (v[0] < 0) continue;
    q.push_back(tri_quality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), 3, m));
  }
  return q;
}

QualityStats surface_stats(const TetMesh& mesh, const std::string& label) {
  return quality_stats_from_values(surface_qualities(mesh, Measure::kQ),
                                   surface_qualities(mesh, Measure::kRadiusRatio),
                                   surface_qualities(mesh, Measure::kMinAngle),
                                   surface_qualities(mesh, Measure::kMaxAngle), 2, label);
}

}  // namespace

std::vector<double> element_qualities(const TetMesh& mesh, Measure m) {
  if (is_surface_mesh(mesh)) return surface_qualities(mesh, m);
  // Per-tet slots filled in parallel, then the dead slots squeezed out in order: the same values
  // in the same order for any number of threads.
  const int nt = mesh.nb_tets();
  std::vector<double> q(nt);
  std::vector<char> live(nt);
#pragma omp parallel for schedule(static, 1024) if (nt > 1024)
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

namespace {

// The partial sums of one block of tets (quality_stats, quality_summary).
struct Part {
  double sum = 0, sum_rr = 0;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  double angle_lo = std::numeric_limits<double>::infinity(), angle_hi = -angle_lo;
  long n = 0;
  QCounts counts;
  void add(const Part& p) {
    n += p.n;
    sum += p.sum;
    sum_rr += p.sum_rr;
    lo = std::min(lo, p.lo);
    hi = std::max(hi, p.hi);
    angle_lo = std::min(angle_lo, p.angle_lo);
    angle_hi = std::max(angle_hi, p.angle_hi);
    counts.add(p.counts);
  }
};

// The live tets in fixed blocks of kBlock, in parallel; each block summed in tet order, the
// blocks in block order: the same figures for any number of threads. `tables` adds the radius
// ratio and the dihedral angles (tet_table_qualities) to Q.
QualityStats reduce_tets(const TetMesh& mesh, const std::string& label, bool tables) {
  const int nt = mesh.nb_tets();
  constexpr int kBlock = 4096;
  const int nb = (nt + kBlock - 1) / kBlock;
  std::vector<Part> parts(static_cast<std::size_t>(nb));
#pragma omp parallel for schedule(static, 4) if (nb > 4)
  for (int b = 0; b < nb; ++b) {
    Part& p = parts[b];
    const int end = std::min(nt, (b + 1) * kBlock);
    for (int t = b * kBlock; t < end; ++t) {
      const int* v = &mesh.tets[4 * static_cast<std::size_t>(t)];
      if (v[0] < 0) continue;
      const double *a = mesh.point(v[0]), *b1 = mesh.point(v[1]), *c = mesh.point(v[2]),
                   *d = mesh.point(v[3]);
      double q;
      if (tables) {
        const std::array<double, 4> all = tet_table_qualities(a, b1, c, d);
        q = all[0];
        p.sum_rr += all[1];
        p.angle_lo = std::min(p.angle_lo, all[2]);
        p.angle_hi = std::max(p.angle_hi, all[3]);
      } else {
        q = tet_quality(a, b1, c, d, Measure::kQ);
      }
      ++p.n;
      p.sum += q;
      p.lo = std::min(p.lo, q);
      p.hi = std::max(p.hi, q);
      p.counts.add(q);
    }
  }
  Part all;
  for (const Part& p : parts) all.add(p);
  QualityStats s;
  s.label = label;
  s.dim = 3;
  s.nb_elements = all.n;
  if (all.n == 0) return s;
  const double n = static_cast<double>(all.n);
  s.q_min = all.lo;
  s.q_max = all.hi;
  s.q_avg = all.sum / n;
  all.counts.fill(s);
  if (tables) {
    s.avg_radius_ratio = all.sum_rr / n;
    s.min_angle = all.angle_lo;
    s.max_angle = all.angle_hi;
  }
  return s;
}

}  // namespace

QualityStats quality_stats(const TetMesh& mesh, const std::string& label) {
  if (is_surface_mesh(mesh)) return surface_stats(mesh, label);
  return reduce_tets(mesh, label, true);
}

QualityStats quality_summary(const TetMesh& mesh, const std::string& label) {
  if (is_surface_mesh(mesh)) return surface_stats(mesh, label);
  return reduce_tets(mesh, label, false);
}

double min_quality(const TetMesh& mesh, Measure m) {
  if (is_surface_mesh(mesh)) {
    double lo = std::numeric_limits<double>::infinity();
    for (double q : surface_qualities(mesh, m)) lo = std::min(lo, q);
    return lo;
  }
  const int nt = mesh.nb_tets();
  double lo = std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static, 1024) reduction(min : lo) if (nt > 1024)
  for (int t = 0; t < nt; ++t) {
    const int* v = &mesh.tets[4 * static_cast<std::size_t>(t)];
    if (v[0] < 0) continue;
    lo = std::min(
        lo, tet_quality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]), m));
  }
  return lo;
}

double min_quality(const TriMesh2& mesh, Measure m) {
  double lo = std::numeric_limits<double>::infinity();
  for (double q : element_qualities(mesh, m)) lo = std::min(lo, q);
  return lo;
}

QualityStats quality_summary(const TriMesh2& mesh, const std::string& label) {
  return quality_stats_from_values(element_qualities(mesh, Measure::kQ), {}, {}, {}, 2, label);
}

QualityStats quality_stats(const TriMesh2& mesh, const std::string& label) {
  QualityStats s = quality_stats_from_values(element_qualities(mesh, Measure::kQ),
                                             element_qualities(mesh, Measure::kRadiusRatio),
                                             element_qualities(mesh, Measure::kMinAngle),
                                             element_qualities(mesh, Measure::kMaxAngle), 2, label);
  // A hybrid mesh's kept quadrangles (kept_quads.h): their rows after the triangles'.
  const KeptQuads q = kept_quads(mesh);
  if (q.nb_quads() == 0) return s;
  double sj_min = std::numeric_limits<double>::infinity(), sj_sum = 0, a_min = 360, a_max = 0;
  for (int k = 0; k < q.nb_quads(); ++k) {
    const int* v = &q.quads[4 * k];
    const double *a = mesh.point(v[0]), *b = mesh.point(v[1]), *c = mesh.point(v[2]),
                 *d = mesh.point(v[3]);
    const double sj = quad_scaled_jacobian(a, b, c, d);
    sj_min = std::min(sj_min, sj);
    sj_sum += sj;
    const QuadAngles qa = quad_angles(a, b, c, d);
    a_min = std::min(a_min, qa.min);
    a_max = std::max(a_max, qa.max);
  }
  s.extra.push_back({"quadrangles", static_cast<double>(q.nb_quads())});
  s.extra.push_back({"quad scaled Jacobian min", sj_min});
  s.extra.push_back({"quad scaled Jacobian avg", sj_sum / q.nb_quads()});
  s.extra.push_back({"quad minimum angle", a_min});
  s.extra.push_back({"quad maximum angle", a_max});
  return s;
}

}  // namespace cvtmesh
