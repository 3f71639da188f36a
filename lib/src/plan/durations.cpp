// arnoldweb: durations that divide each other (durations.hpp).
#include "plan/durations.hpp"

#include <cmath>

namespace arnoldweb::detail {

std::int64_t exact_ratio(double x, double unit) {
  const double r = x / unit;
  if (!(r < 9.0e15)) return 0;  // beyond exact integers in a double (and NaN)
  const double n = std::nearbyint(r);
  if (n < 1 || std::fabs(r - n) > 1e-9 * n) return 0;
  return static_cast<std::int64_t>(n);
}

}  // namespace arnoldweb::detail
