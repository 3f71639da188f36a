// arnoldweb: the step-size guard. Splitting methods resonate when h omega
// reaches pi, omega the largest frequency of the model along a trajectory; the
// guard refuses such steps and advises one at pi/2 (docs/numerics.md).
#pragma once

#include <string>

namespace arnoldweb {

// The step-size guard: h k |p|max against the splitting resonance at pi.
struct StepGuard {
  double p_max = 0;     // sqrt(2 (E + 2)): largest momentum on the shell (other models: omega / 2)
  double value = 0;     // h omega with h in time units (step * 2 pi); the paper's model: omega = k |p|max, k = 2
  double omega = 0;     // the model's largest frequency (radians per time unit)
  std::string basis;    // how omega was found, for messages
  std::string quantity; // what `value` is, for messages: "h k |p|max" (the paper's model), "h omega_max"
  double limit = 0;     // pi: refuse at or above
  double advised = 0;   // pi / 2: warn above
  double safe_step = 0; // largest step (in T) dividing the schedule with value <= advised
  bool refused() const { return value >= limit; }
  bool warned() const { return value > advised; }
};
StepGuard step_guard(double energy, double step, double average, double energy_every);  // the paper's model
StepGuard step_guard_at(double omega, double step, double average, double energy_every);  // any omega

}  // namespace arnoldweb
