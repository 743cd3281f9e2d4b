// The .geo text that shows a quality view (the .opt of `optimize --quality` and the ONELAB
// client): the range skips non-finite values, the other views are hidden, a 2D mesh is not cut.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/io/quality_view_geo.h"

namespace cvtmesh {
namespace {

TEST(QualityViewGeo, RangeSkipsNonFiniteValuesAndIsNeverEmpty) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double lo = 0, hi = 0;
  finite_range({"Q", {nan, 0.25, 0.75, nan, 0.5}}, lo, hi);
  EXPECT_EQ(lo, 0.25);
  EXPECT_EQ(hi, 0.75);
  finite_range({"Q", {0.5, 0.5}}, lo, hi);
  EXPECT_EQ(lo, 0.5);
  EXPECT_GT(hi, lo);
}

TEST(QualityViewGeo, FirstViewRangedOthersHiddenNoCutIn2D) {
  MeshData d;
  d.dim = 2;
  const std::string s =
      quality_view_geo(d, {{"Q", {0.2, 0.9}}, {"radius ratio", {0.3, 1}}}, "cvt_q");
  EXPECT_NE(s.find("View[cvt_q].RangeType = 2;"), std::string::npos);
  EXPECT_NE(s.find("View[cvt_q].CustomMin = 0.2"), std::string::npos);
  EXPECT_NE(s.find("View[cvt_q].CustomMax = 0.9"), std::string::npos);
  EXPECT_NE(s.find("View[cvt_q + 1].Visible = 0;"), std::string::npos);
  EXPECT_EQ(s.find("Clip"), std::string::npos);
  EXPECT_TRUE(quality_view_geo(d, {}, "0").empty());
}

}  // namespace
}  // namespace cvtmesh
