// arnoldweb: durations that must divide each other (a step into a window, a
// window into a run): exact within rounding.
#pragma once

#include <cstdint>

namespace arnoldweb::detail {

// n if x / unit is within rounding of an integer n >= 1 (and below 9e15), else 0.
std::int64_t exact_ratio(double x, double unit);

}  // namespace arnoldweb::detail
