#include "core/util/on_both.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace cvtmesh {
namespace {

// A serial pass whose value depends on the order of its sums (as the verification's passes do).
std::map<int, double> pass(const std::vector<double>& x) {
  std::map<int, double> m;
  for (std::size_t i = 0; i < x.size(); ++i) m[static_cast<int>(i % 7)] += x[i] * 1e-3 + 1.0 / 3;
  return m;
}

std::vector<double> values(int n, double s) {
  std::vector<double> x(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) x[i] = std::sin(s * i) * 1e6;
  return x;
}

TEST(OnBoth, SameValuesAsOneAfterTheOtherForAnyThreadCount) {
  const std::vector<double> a = values(100000, 0.37), b = values(90001, 1.91);
  const auto serial_a = pass(a), serial_b = pass(b);
  const int was = omp_get_max_threads();
  for (int threads : {1, 2, 4}) {
    omp_set_num_threads(threads);
    const auto r = on_both(a, b, pass);
    EXPECT_EQ(r.first, serial_a) << threads;
    EXPECT_EQ(r.second, serial_b) << threads;
  }
  omp_set_num_threads(was);
}

TEST(OnBoth, RethrowsTheFirstSidesException) {
  auto f = [](int side) -> int {
    if (side > 0) throw std::runtime_error("side " + std::to_string(side));
    return side;
  };
  try {
    on_both(1, 2, f);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "side 1");
  }
  try {
    on_both(0, 2, f);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "side 2");
  }
  EXPECT_EQ(on_both(0, 0, f), std::make_pair(0, 0));
}

}  // namespace
}  // namespace cvtmesh
