// The quality histogram (pure) and its SVG picture.
#include <gtest/gtest.h>

#include <numeric>
#include <string>

#include "core/io/histogram_svg.h"
#include "core/quality/quality_histogram.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

TEST(QualityHistogram, BinsAndFractions) {
  const std::vector<double> q = {-0.1, 0.0, 0.05, 0.29, 0.31, 0.5, 0.999, 1.0};
  const QualityHistogram h = quality_histogram(q, 10, "m");
  ASSERT_EQ(h.fraction.size(), 10u);
  EXPECT_NEAR(std::accumulate(h.fraction.begin(), h.fraction.end(), 0.0), 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(h.fraction[0], 3.0 / 8);  // -0.1, 0.0 and 0.05
  EXPECT_DOUBLE_EQ(h.fraction[2], 1.0 / 8);  // 0.29
  EXPECT_DOUBLE_EQ(h.fraction[3], 1.0 / 8);  // 0.31
  EXPECT_DOUBLE_EQ(h.fraction[5], 1.0 / 8);  // 0.5
  EXPECT_DOUBLE_EQ(h.fraction[9], 2.0 / 8);  // 0.999 and exactly 1
  EXPECT_EQ(h.nb_inverted, 2);
  EXPECT_EQ(h.nb_elements, 8);
  EXPECT_DOUBLE_EQ(h.q_min, -0.1);
  EXPECT_THROW(quality_histogram(q, 0, "m"), std::invalid_argument);
  const QualityHistogram e = quality_histogram({}, 4, "empty");
  EXPECT_EQ(e.nb_elements, 0);
  EXPECT_EQ(std::accumulate(e.fraction.begin(), e.fraction.end(), 0.0), 0.0);
}

TEST(QualityHistogram, SvgHasOneOutlinePerMeshAndEscapesLabels) {
  const auto a = quality_histogram({0.2, 0.8, 0.9}, 20, "a<&>");
  const auto b = quality_histogram({0.6, 0.7}, 20, "b");
  const std::string svg = histogram_svg({a, b});
  auto count = [&](const std::string& what) {
    int n = 0;
    for (auto at = svg.find(what); at != std::string::npos; at = svg.find(what, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("<polygon"), 2);
  EXPECT_NE(svg.find("a&lt;&amp;&gt;"), std::string::npos);
  EXPECT_EQ(svg.find("a<&>"), std::string::npos);
  EXPECT_EQ(svg.rfind("</svg>"), svg.size() - 7);
  EXPECT_THROW(check_histogram_path("/tmp/x.bmp"), OutputError);
  EXPECT_THROW(check_histogram_path("/no/such/dir/x.svg"), OutputError);
}

}  // namespace
}  // namespace cvtmesh
