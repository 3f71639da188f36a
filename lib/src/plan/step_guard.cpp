// arnoldweb: the step-size guard (step_guard.hpp). Splitting methods resonate when
// h omega reaches pi, omega the largest frequency of the model along a
// trajectory (the paper's model: k |p|max, k = 2 the largest wave number of
// the force, for z; other models: model_plan.cpp's model_frequency); the guard
// refuses such steps and advises one at pi/2.
#include <algorithm>
#include <cmath>

#include "arnoldweb/step_guard.hpp"
#include "plan/durations.hpp"

namespace arnoldweb {

StepGuard step_guard(double energy, double step, double average, double energy_every) {
  const double p_max = std::sqrt(2.0 * (energy + 2.0));
  StepGuard g = step_guard_at(2.0 * p_max, step, average, energy_every);
  g.p_max = p_max;
  return g;
}

StepGuard step_guard_at(double omega, double step, double average, double energy_every) {
  constexpr double kTwoPi = 6.283185307179586476925;
  StepGuard g;
  g.omega = omega;
  g.p_max = omega / 2.0;
  g.value = step * kTwoPi * omega;
  g.limit = M_PI;
  g.advised = M_PI / 2;
  const double s_max = g.advised / (kTwoPi * omega);
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
