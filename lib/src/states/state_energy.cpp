// arnoldweb: initial states against the scene's model (states.hpp:
// check_states, load_initial_states) and what the planner asks of
// ensemble.initial = "file" (state_plan.hpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/states.hpp"
#include "physics/models.hpp"
#include "states/state_plan.hpp"
#include "states/state_rules.hpp"

namespace arnoldweb {

void check_states(StateSet& s, const Scene& scene) {
  const detail::ModelRow& model = detail::model_of(scene);
  detail::RealParams rp{};
  model.fill(scene, rp);
  const std::array<double, 6> k = model.kinetic(rp);  // T = sum a_i p_i^2 / 2 + b_i p_i
  const std::array<double, 2> v = model.v_range(rp);
  const double e = scene.energy;
  const double scale = std::max(std::fabs(e), v[1] - v[0]);
  const double tolerance = kStateEnergyTolerance * scale;
  s.energy.assign(s.count, std::numeric_limits<double>::quiet_NaN());
  s.energy_min = std::numeric_limits<double>::infinity();
  s.energy_max = -s.energy_min;
  for (std::uint64_t i = 0; i < s.count; ++i) {
    if (s.status[i] != 0) continue;
    const double* u = &s.position_turns[3 * i];
    const double* p = &s.momentum[3 * i];
    double t = 0;
    for (int c = 0; c < 3; ++c) t += k[c] * p[c] * p[c] / 2 + k[3 + c] * p[c];
    const double h = t + model.potential(u[0], u[1], u[2], rp);
    if (!std::isfinite(h) || std::fabs(h - e) > tolerance)
      throw StateError(s.source, "", static_cast<std::int64_t>(i),
                       "the state's energy H = T(P) + V(X) = " + detail::show_number(h) +
                           " is far from model.energy = " + detail::show_number(e) + " (|H - E| = " +
                           detail::show_number(std::fabs(h - e)) + " > " + detail::show_number(tolerance) + ", " +
                           detail::show_number(100 * kStateEnergyTolerance) +
                           "% of max(|E|, max V - min V)); position " + detail::show_row(u) +
                           " turns, momentum " + detail::show_row(p) +
                           ". Are the positions in the units said, the momenta those of this model?");
    s.energy[i] = h;
    s.energy_min = std::min(s.energy_min, h);
    s.energy_max = std::max(s.energy_max, h);
  }
  if (s.energy_min > s.energy_max) s.energy_min = s.energy_max = 0;  // no state checked
}

StateSet load_initial_states(const Scene& scene) {
  StateSet s = read_state_file(scene.initial_file);
  check_states(s, scene);
  return s;
}

namespace detail {

void plan_initial_states(const Scene& scene) {
  if (scene.initial != "file") {
    if (!scene.initial_file.empty())
      fail_at(scene, "ensemble.file",
              "is read only with ensemble.initial = \"file\" (ensemble.initial is \"" + scene.initial + "\")");
    return;
  }
  if (scene.initial_file.empty())
    fail_at(scene, "ensemble.initial", "\"file\" needs ensemble.file = \"path.h5\", the HDF5 file of the states");
  // The file is read and checked now, so that `arnoldweb check` names a bad row before any run.
  const StateSet states = load_initial_states(scene);
  // issue 25, item 1: the kernels cannot start from stored states yet (the lead's part).
  fail_at(scene, "ensemble.initial",
          "\"file\" is not yet run: " + std::to_string(states.count) + " states of " + states.source +
              " were read and checked, but the kernels cannot start from stored states yet (issue 25, item 1)");
}

}  // namespace detail
}  // namespace arnoldweb
