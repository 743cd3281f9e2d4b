// The "never worse than the input" criterion: each measure on its own makes a mesh worse.
#include "core/quality/worse_than.h"

#include <gtest/gtest.h>

namespace cvtmesh {
namespace {

QualityStats stats(double q_min, double q_avg, double min_angle, double max_angle) {
  QualityStats s;
  s.q_min = q_min, s.q_avg = q_avg, s.min_angle = min_angle, s.max_angle = max_angle;
  return s;
}

TEST(WorseThan, EachMeasureAloneMakesAMeshWorseAndEqualIsNot) {
  const QualityStats in = stats(0.2, 0.70, 10, 160);
  EXPECT_EQ(worse_than(in, in), "");
  EXPECT_EQ(worse_than(stats(0.3, 0.80, 20, 150), in), "");
  EXPECT_EQ(worse_than(stats(0.1, 0.80, 20, 150), in), "Q_min 0.2000 -> 0.1000");
  EXPECT_EQ(worse_than(stats(0.3, 0.80, 9, 150), in), "min dihedral 10.00 -> 9.00 degrees");
  EXPECT_EQ(worse_than(stats(0.3, 0.80, 20, 161), in), "max dihedral 160.00 -> 161.00 degrees");
  // Issue 14: better extremes with a lower average (t15: 0.6985 -> 0.6967) are worse too.
  EXPECT_EQ(worse_than(stats(0.3, 0.69, 20, 150), in), "average Q 0.7000 -> 0.6900");
  QualityStats flat = in;
  flat.nb_inverted = 1;
  EXPECT_EQ(worse_than(flat, in), "1 inverted or flat elements");
}

// Within its tolerance a row is not worse; past it, it is (and the message names it); inverted
// elements are never tolerated.
TEST(WorseThan, ARowWithinItsToleranceIsNotWorse) {
  const QualityStats in = stats(0.2, 0.70, 10, 160);
  RowTolerance tol;
  tol.q_min_relative = 0.01, tol.q_avg = 0.001, tol.angle = 0.1;
  EXPECT_EQ(worse_than(stats(0.1985, 0.6995, 9.95, 160.05), in, tol), "");
  EXPECT_EQ(worse_than(stats(0.1975, 0.70, 10, 160), in, tol), "Q_min 0.2000 -> 0.1975");
  EXPECT_EQ(worse_than(stats(0.2, 0.6985, 10, 160), in, tol), "average Q 0.7000 -> 0.6985");
  EXPECT_EQ(worse_than(stats(0.2, 0.70, 9.85, 160), in, tol), "min dihedral 10.00 -> 9.85 degrees");
  EXPECT_EQ(worse_than(stats(0.2, 0.70, 10, 160.15), in, tol),
            "max dihedral 160.00 -> 160.15 degrees");
  QualityStats flat = in;
  flat.nb_inverted = 1;
  EXPECT_EQ(worse_than(flat, in, tol), "1 inverted or flat elements");
  // The default tolerance is none: the exact comparison.
  EXPECT_EQ(worse_than(stats(0.1999, 0.70, 10, 160), in, RowTolerance{}), "Q_min 0.2000 -> 0.1999");
}

// On balance (auto_refine): past the tolerance on both Q rows and a gain in sum, each row counted
// in units of its tolerance; igl_3holes' refined run (stop 39) is one.
TEST(WorseThan, BetterOnBalanceTradesALittleOfAnAngleRowForMuchOnBothQRows) {
  RowTolerance tol;
  tol.q_min_relative = 0.01, tol.q_avg = 0.001, tol.angle = 0.1;
  const QualityStats plain = stats(0.3967, 0.8536, 20.36, 133.22);
  const QualityStats refined = stats(0.4398, 0.8627, 23.58, 136.74);
  EXPECT_NE(worse_than(refined, plain, tol), "");
  EXPECT_TRUE(better_on_balance(refined, plain, tol));
  // Gmsh t20's 1.5 run: both Q rows a little better, the maximum angle 2.6 degrees worse.
  EXPECT_FALSE(better_on_balance(stats(0.0535, 0.7391, 3.19, 166.30),
                                 stats(0.0521, 0.7367, 3.07, 163.67), tol));
  // One Q row not better past its tolerance: never, whatever the angles gain.
  EXPECT_FALSE(better_on_balance(stats(0.3967, 0.90, 30, 120), plain, tol));
  EXPECT_FALSE(better_on_balance(stats(0.45, 0.8536, 30, 120), plain, tol));
  // More inverted elements, or no tolerance: never.
  QualityStats flat = refined;
  flat.nb_inverted = 1;
  EXPECT_FALSE(better_on_balance(flat, plain, tol));
  EXPECT_FALSE(better_on_balance(refined, plain, RowTolerance{}));
}

}  // namespace
}  // namespace cvtmesh
