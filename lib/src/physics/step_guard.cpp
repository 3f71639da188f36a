// arnoldweb: the step-size guard (plan.hpp). Splitting methods resonate when
// h k |p| reaches pi (k: the largest wave number of the force, 2 for z in the
// paper's model); the guard refuses such steps and advises one at pi/2.
#include <algorithm>
#include <cmath>

#include "arnoldweb/plan.hpp"
#include "plan/checks.hpp"

namespace arnoldweb {

StepGuard step_guard(double energy, double step, double average, double energy_every) {
  constexpr double kTwoPi = 6.283185307179586476925;
  StepGuard g;
  g.p_max = std::sqrt(2.0 * (energy + 2.0));
  g.value = step * kTwoPi * 2.0 * g.p_max;
  g.limit = M_PI;
  g.advised = M_PI / 2;
  const double s_max = g.advised / (kTwoPi * 2.0 * g.p_max);
  const double unit = (energy_every > 0 && energy_every <= average) ? energy_every : average;
  // prefer a round number (1, 2, 2.5, 4, 5 x 10^k) that divides the schedule
  for (double decade = std::pow(10.0, std::floor(std::log10(s_max))); decade > 1e-9 * s_max; decade /= 10)
    for (double mantissa : {5.0, 4.0, 2.5, 2.0, 1.0}) {
      const double s = mantissa * decade;
      if (s <= s_max && detail::exact_ratio(unit, s) > 0 && detail::exact_ratio(average, s) > 0) {
        g.safe_step = s;
        return g;
      }
    }
  g.safe_step = unit / std::max(1.0, std::ceil(unit / s_max - 1e-12));
  return g;
}

}  // namespace arnoldweb
