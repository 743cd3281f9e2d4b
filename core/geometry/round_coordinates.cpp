#include "core/geometry/round_coordinates.h"

#include <charconv>
#include <cstddef>

namespace cvtmesh {

double round_to_digits(double x, int digits) {
  // std::to_chars with a precision writes what printf's "%.*g" writes (the C locale), and
  // from_chars reads it back correctly rounded as strtod does: the same value, without the
  // locale and format parsing (3M coordinates of a 1M-tet mesh: about 1.5 s with snprintf).
  char buf[64];
  const auto w = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, digits);
  double y = x;
  std::from_chars(buf, w.ptr, y);
  return y;
}

void round_coordinates(std::vector<double>& xyz, int digits, const std::vector<char>& which) {
  if (digits <= 0 || digits >= 17) return;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(xyz.size());
#pragma omp parallel for schedule(static, 4096) if (n > 4096)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    if (which.empty() || which[i / 3]) xyz[i] = round_to_digits(xyz[i], digits);
}

}  // namespace cvtmesh
