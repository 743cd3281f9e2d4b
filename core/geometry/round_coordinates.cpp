#include "core/geometry/round_coordinates.h"

#include <cstdio>
#include <cstdlib>

namespace cvtmesh {

double round_to_digits(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return std::strtod(buf, nullptr);
}

void round_coordinates(std::vector<double>& xyz, int digits, const std::vector<char>& which) {
  if (digits <= 0 || digits >= 17) return;
  for (std::size_t i = 0; i < xyz.size(); ++i)
    if (which.empty() || which[i / 3]) xyz[i] = round_to_digits(xyz[i], digits);
}

}  // namespace cvtmesh
