#include "core/quality/quality.h"

#include <gtest/gtest.h>

#include <cstdint>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

#include "core/geometry/tet_geometry.h"
#include "core/quality/quality_stats.h"
#include "core/quality/quality_table.h"
#include "tests/support/test_meshes.h"
#include "tests/support/thread_counts.h"

namespace cvtmesh {
namespace {

const double kRegular[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};

TEST(TetQuality, RegularTetIsOneForEveryShapeMeasure) {
  // kRegular as listed is negatively oriented (Q = -1); swapping two vertices makes it positive.
  EXPECT_NEAR(tet_quality(kRegular[0], kRegular[1], kRegular[2], kRegular[3], Measure::kQ), -1.0,
              1e-12);
  EXPECT_NEAR(tet_quality(kRegular[1], kRegular[0], kRegular[2], kRegular[3], Measure::kQ), 1.0,
              1e-12);
  const double a[3] = {1, 1, 1}, b[3] = {-1, 1, -1}, c[3] = {1, -1, -1}, d[3] = {-1, -1, 1};
  const double s = tet_quality(a, b, c, d, Measure::kQ);
  EXPECT_NEAR(std::fabs(s), 1.0, 1e-12);
  const double sign = s > 0 ? 1 : -1;
  const double* pa = sign > 0 ? a : b;
  const double* pb = sign > 0 ? b : a;
  EXPECT_NEAR(tet_quality(pa, pb, c, d, Measure::kQ), 1.0, 1e-12);
  EXPECT_NEAR(tet_quality(pa, pb, c, d, Measure::kRadiusRatio), 1.0, 1e-12);
  EXPECT_NEAR(tet_quality(pa, pb, c, d, Measure::kGmshIcn), 1.0, 1e-12);
  EXPECT_NEAR(tet_quality(pa, pb, c, d, Measure::kMinAngle), std::acos(1.0 / 3) * 180 / M_PI, 1e-9);
  EXPECT_NEAR(tet_quality(pa, pb, c, d, Measure::kMaxAngle), std::acos(1.0 / 3) * 180 / M_PI, 1e-9);
}

TEST(TetQuality, BccTetIsAbout0_9295) {
  // The BCC lattice tet: two opposite edges of length 2 (cube edges) and four of length sqrt(3).
  const double a[3] = {0, 0, 0}, b[3] = {2, 0, 0}, c[3] = {1, 1, 1}, d[3] = {1, 1, -1};
  double v = tet_quality(a, b, c, d, Measure::kQ);
  if (v < 0) v = tet_quality(b, a, c, d, Measure::kQ);
  // 72*sqrt3*V/(sum L^2)^1.5 with V = 2/3, sum L^2 = 2*4 + 4*3 = 20.
  EXPECT_NEAR(v, 72 * std::sqrt(3.0) * (2.0 / 3) / std::pow(20.0, 1.5), 1e-12);
  EXPECT_NEAR(v, 0.9295, 5e-5);
}

TEST(TetQuality, FlatTetIsZeroAndInvertedIsNegative) {
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, d[3] = {0.3, 0.3, 0};
  EXPECT_EQ(tet_quality(a, b, c, d, Measure::kQ), 0.0);
  EXPECT_EQ(tet_quality(a, b, c, d, Measure::kRadiusRatio), 0.0);
  const double e[3] = {0, 0, 1};
  const double pos = tet_quality(a, b, c, e, Measure::kQ);
  const double neg = tet_quality(b, a, c, e, Measure::kQ);
  EXPECT_GT(pos, 0);
  EXPECT_DOUBLE_EQ(neg, -pos);
  EXPECT_LT(tet_quality(b, a, c, e, Measure::kRadiusRatio), 0);
  EXPECT_LT(tet_quality(b, a, c, e, Measure::kGmshIcn), 0);
  EXPECT_LT(tet_quality(b, a, c, e, Measure::kMinAngle), 0);
}

TEST(TetQuality, SameBitsForEveryOrientationPreservingVertexOrder) {
  // A sliver: a skewed square whose corners are 1e-14 above / below z = 0.3. Its volume rounds
  // differently in different vertex orders; its quality must not (the swaps rely on it).
  const double e = 1e-14;
  const double p[4][3] = {
      {0.1, 0.2, 0.3 + e}, {1.1, 0.23, 0.3 - e}, {1.13, 1.17, 0.3 + e}, {0.07, 1.21, 0.3 - e}};
  int o[4] = {0, 1, 2, 3};
  if (!(tet_volume(p[0], p[1], p[2], p[3]) > 0)) std::swap(o[2], o[3]);
  // The 12 even permutations of o: the rotations of (1,2,3) around each vertex in turn.
  std::vector<std::array<int, 4>> even;
  for (int first = 0; first < 4; ++first) {
    std::array<int, 4> q{};
    q[0] = o[first];
    // The remaining three in an order that keeps the permutation even.
    const int rest[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    for (int r = 0; r < 3; ++r) {
      for (int k = 0; k < 3; ++k) q[1 + k] = o[rest[first][(r + k) % 3]];
      even.push_back(q);
    }
  }
  std::set<double> volumes;
  for (const auto& q : even) volumes.insert(tet_volume(p[q[0]], p[q[1]], p[q[2]], p[q[3]]));
  EXPECT_GT(volumes.size(), 1u) << "the raw volume does not depend on the order here";
  for (Measure m : {Measure::kQ, Measure::kRadiusRatio, Measure::kMinAngle, Measure::kMaxAngle,
                    Measure::kGmshIcn}) {
    const double ref = tet_quality(p[o[0]], p[o[1]], p[o[2]], p[o[3]], m);
    for (const auto& q : even)
      EXPECT_EQ(tet_quality(p[q[0]], p[q[1]], p[q[2]], p[q[3]], m), ref)
          << measure_name(m) << " order " << q[0] << q[1] << q[2] << q[3];
  }
}

TEST(TetQuality, CornerTetDihedralAngles) {
  // The corner tet of the unit cube: three right dihedral angles at the axes, three of
  // acos(1/sqrt3) = 54.7356 deg at the slanted face.
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, d[3] = {0, 0, 1};
  EXPECT_NEAR(tet_quality(a, b, c, d, Measure::kMaxAngle), 90.0, 1e-9);
  EXPECT_NEAR(tet_quality(a, b, c, d, Measure::kMinAngle),
              std::acos(1 / std::sqrt(3.0)) * 180 / M_PI, 1e-9);
  // Q = 72 sqrt3 (1/6) / (3 + 3*2)^1.5
  EXPECT_NEAR(tet_quality(a, b, c, d, Measure::kQ), 12 * std::sqrt(3.0) / 27.0, 1e-12);
}

// The table's four measures at once are tet_quality's to the bit, and the min / max dihedral
// angles are those of tet_dihedral_angles: on random tets of both orientations, flat ones and
// slivers.
TEST(TetQuality, TheTableMeasuresAtOnceAreEachMeasuresBits) {
  unsigned state = 2024;
  auto rnd = [&] {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / double(1 << 24);
  };
  const double e = 1e-14;
  std::vector<std::array<std::array<double, 3>, 4>> tets = {
      {{{0.1, 0.2, 0.3 + e}, {1.1, 0.23, 0.3 - e}, {1.13, 1.17, 0.3 + e}, {0.07, 1.21, 0.3 - e}}},
      {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 0}}}};
  for (int i = 0; i < 2000; ++i) {
    std::array<std::array<double, 3>, 4> t{};
    for (auto& p : t)
      for (double& x : p) x = rnd();
    if (i % 3 == 0)  // a near-sliver: the fourth point close to the plane of the first three
      for (int k = 0; k < 3; ++k)
        t[3][k] = (t[0][k] + t[1][k] + t[2][k]) / 3 + 1e-3 * (rnd() - 0.5);
    tets.push_back(t);
  }
  for (const auto& t : tets) {
    const double *a = t[0].data(), *b = t[1].data(), *c = t[2].data(), *d = t[3].data();
    const auto all = tet_table_qualities(a, b, c, d);
    EXPECT_EQ(all[0], tet_quality(a, b, c, d, Measure::kQ));
    EXPECT_EQ(all[1], tet_quality(a, b, c, d, Measure::kRadiusRatio));
    EXPECT_EQ(all[2], tet_quality(a, b, c, d, Measure::kMinAngle));
    EXPECT_EQ(all[3], tet_quality(a, b, c, d, Measure::kMaxAngle));
    const auto ang = tet_dihedral_angles(a, b, c, d);
    const double lo = *std::min_element(ang.begin(), ang.end()) * 180 / M_PI;
    const double hi = *std::max_element(ang.begin(), ang.end()) * 180 / M_PI;
    EXPECT_NEAR(std::fabs(all[2]), lo, 1e-9);
    EXPECT_NEAR(all[3], hi, 1e-9);
  }
}

TEST(TriQuality, MinMaxAngleAtOnceIsBitwiseTheSingleMeasures) {
  std::uint32_t state = 12345;
  auto rnd = [&] {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / double(1 << 24);
  };
  for (int i = 0; i < 2000; ++i) {
    double p[3][3];
    for (auto& q : p)
      for (double& x : q) x = rnd();
    if (i % 4 == 0)  // nearly flat: the third point close to the line of the first two
      for (int k = 0; k < 3; ++k) p[2][k] = 0.5 * (p[0][k] + p[1][k]) + 1e-9 * (rnd() - 0.5);
    for (int dim : {2, 3}) {
      const auto both = tri_min_max_angle(p[0], p[1], p[2], dim);
      EXPECT_EQ(both[0], tri_quality(p[0], p[1], p[2], dim, Measure::kMinAngle));
      EXPECT_EQ(both[1], tri_quality(p[0], p[1], p[2], dim, Measure::kMaxAngle));
      // Clockwise in 2D: the minimum angle negative, as tri_quality's.
      const auto turned = tri_min_max_angle(p[1], p[0], p[2], dim);
      EXPECT_EQ(turned[0], tri_quality(p[1], p[0], p[2], dim, Measure::kMinAngle));
    }
  }
}

TEST(TriQuality, EquilateralIsOneAndKnownAngles) {
  const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0.5, std::sqrt(3.0) / 2};
  EXPECT_NEAR(tri_quality(a, b, c, 2, Measure::kQ), 1.0, 1e-12);
  EXPECT_NEAR(tri_quality(a, b, c, 2, Measure::kRadiusRatio), 1.0, 1e-12);
  EXPECT_NEAR(tri_quality(a, b, c, 2, Measure::kMinAngle), 60.0, 1e-9);
  EXPECT_NEAR(tri_quality(a, c, b, 2, Measure::kQ), -1.0, 1e-12);
  // Right isosceles: angles 45, 45, 90; Q = 4 sqrt3 * 0.5 / (1 + 1 + 2).
  const double d[2] = {0, 1};
  EXPECT_NEAR(tri_quality(a, b, d, 2, Measure::kMinAngle), 45.0, 1e-9);
  EXPECT_NEAR(tri_quality(a, b, d, 2, Measure::kMaxAngle), 90.0, 1e-9);
  EXPECT_NEAR(tri_quality(a, b, d, 2, Measure::kQ), std::sqrt(3.0) / 2, 1e-12);
  // The 30-60-90 triangle.
  const double e[2] = {std::sqrt(3.0), 0}, f[2] = {0, 1};
  EXPECT_NEAR(tri_quality(a, e, f, 2, Measure::kMinAngle), 30.0, 1e-9);
  EXPECT_NEAR(tri_quality(a, e, f, 2, Measure::kMaxAngle), 90.0, 1e-9);
  // The same triangle in 3D coordinates.
  const double a3[3] = {0, 0, 5}, b3[3] = {1, 0, 5}, c3[3] = {0.5, std::sqrt(3.0) / 2, 5};
  EXPECT_NEAR(tri_quality(a3, b3, c3, 3, Measure::kQ), 1.0, 1e-12);
}

TEST(QualityStats, BinsAndPercentagesOnAHandMadeSet) {
  // Values on and around each bin boundary: the paper's bins are half-open, (lo, hi].
  const std::vector<double> qv = {1.0, 0.71, 0.7, 0.5, 0.51, 0.3, 0.31, 0.29, 0.01, -0.2};
  const auto s = quality_stats_from_values(qv, qv, {10, 20}, {100, 170}, 3, "set");
  EXPECT_EQ(s.nb_elements, 10);
  EXPECT_EQ(s.bin[0], 2);  // 1.0, 0.71
  EXPECT_EQ(s.bin[1], 2);  // 0.7, 0.51
  EXPECT_EQ(s.bin[2], 2);  // 0.5, 0.31
  EXPECT_EQ(s.bin[3], 3);  // 0.3, 0.29, 0.01
  EXPECT_EQ(s.nb_inverted, 1);
  EXPECT_DOUBLE_EQ(s.q_min, -0.2);
  // bad: Q < 0.3 -> 0.29, 0.01, -0.2 ; good: Q > 0.5 -> 1.0, 0.71, 0.7, 0.51
  EXPECT_DOUBLE_EQ(s.bad_pct, 30.0);
  EXPECT_DOUBLE_EQ(s.good_pct, 40.0);
  EXPECT_DOUBLE_EQ(s.min_angle, 10);
  EXPECT_DOUBLE_EQ(s.max_angle, 170);
  double sum = 0;
  for (double v : qv) sum += v;
  EXPECT_DOUBLE_EQ(s.q_avg, sum / 10);
}

TEST(QualityStats, OnePassOverTheTetsMatchesThePerElementValuesForAnyThreadCount) {
  // A jittered lattice's Delaunay mesh (every kind of tet, more than one block of 4096) with a
  // dead slot: the one-pass statistics are those of the per-element values (the average to
  // rounding: summed in blocks), the same bits for 1, 2 and 3 threads; min_quality is their
  // minimum.
  TetMesh m = testing::delaunay_of_points(testing::cube_lattice(14, 0.3));
  ASSERT_GT(m.nb_tets(), 2 * 4096);
  for (int k = 0; k < 4; ++k) m.tets[4 * 5 + k] = -1;
  const auto ref = quality_stats_from_values(
      element_qualities(m, Measure::kQ), element_qualities(m, Measure::kRadiusRatio),
      element_qualities(m, Measure::kMinAngle), element_qualities(m, Measure::kMaxAngle), 3, "");
  ASSERT_EQ(ref.nb_elements, m.nb_tets() - 1);
  const auto runs = testing::for_each_thread_count(
      [&] { return std::make_pair(quality_stats(m, ""), quality_summary(m, "")); });
  for (const auto& [s, q] : runs) {
    EXPECT_EQ(s.nb_elements, ref.nb_elements);
    for (int b = 0; b < 4; ++b) EXPECT_EQ(s.bin[b], ref.bin[b]);
    EXPECT_EQ(s.q_min, ref.q_min);
    EXPECT_EQ(s.q_max, ref.q_max);
    EXPECT_EQ(s.min_angle, ref.min_angle);
    EXPECT_EQ(s.max_angle, ref.max_angle);
    EXPECT_EQ(s.bad_pct, ref.bad_pct);
    EXPECT_EQ(s.good_pct, ref.good_pct);
    EXPECT_NEAR(s.q_avg, ref.q_avg, 1e-12);
    EXPECT_NEAR(s.avg_radius_ratio, ref.avg_radius_ratio, 1e-12);
    EXPECT_EQ(s.q_avg, runs.front().first.q_avg);
    EXPECT_EQ(s.avg_radius_ratio, runs.front().first.avg_radius_ratio);
    // The summary's Q rows are the full statistics' bit for bit.
    EXPECT_EQ(q.q_avg, s.q_avg);
    EXPECT_EQ(q.q_min, s.q_min);
    EXPECT_EQ(q.bin[3], s.bin[3]);
  }
  EXPECT_EQ(min_quality(m, Measure::kQ), ref.q_min);
  EXPECT_EQ(min_quality(m, Measure::kMinAngle), ref.min_angle);
}

TEST(QualityTable, HasThePaperRowsInTextMarkdownAndJson) {
  const std::vector<double> qv = {0.9, 0.6, 0.4, 0.2};
  QualityTable t;
  t.columns.push_back(quality_stats_from_values(qv, qv, {20}, {120}, 3, "Init"));
  auto opt = quality_stats_from_values({0.95, 0.9}, {0.9, 0.9}, {40}, {100}, 3, "CVDT+SWAP");
  opt.extra.push_back({"iterations", 12});
  t.columns.push_back(opt);
  const std::string text = t.to_text();
  for (const char* row :
       {"number of elements", "0.7 < Q <= 1.0", "0.5 < Q <= 0.7", "0.3 < Q <= 0.5",
        "0.0 < Q <= 0.3", "Q_min", "bad elements (%)", "good elements (%)", "average quality",
        "min dihedral angle", "max dihedral angle", "iterations"})
    EXPECT_NE(text.find(row), std::string::npos) << row;
  EXPECT_NE(text.find("CVDT+SWAP"), std::string::npos);
  EXPECT_EQ(text.find("inverted"), std::string::npos);  // no inverted element: no such row
  const std::string md = t.to_markdown();
  EXPECT_NE(md.find("| Init | CVDT+SWAP |"), std::string::npos);
  EXPECT_NE(md.find("| bad elements (%) | 25.00 | 0.00 |"), std::string::npos);
  const std::string js = t.to_json();
  EXPECT_NE(js.find("\"average_quality\""), std::string::npos);
  EXPECT_NE(js.find("\"iterations\": 12"), std::string::npos);
  // 2D tables carry the rows of Tables 1-5.
  QualityTable t2;
  t2.columns.push_back(quality_stats_from_values(qv, qv, {20}, {120}, 2, "RandPert"));
  const std::string text2 = t2.to_text();
  for (const char* row : {"average quality", "minimum quality", "minimum angle", "maximum angle"})
    EXPECT_NE(text2.find(row), std::string::npos) << row;
  EXPECT_EQ(text2.find("0.7 < Q"), std::string::npos);
}

}  // namespace
}  // namespace cvtmesh
