// arnoldweb: the energies of given states under a model, each far from the
// scene's energy refused naming the row (state_energy.hpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "arnoldweb/errors.hpp"
#include "plan/checks.hpp"
#include "states/state_energy.hpp"
#include "states/state_rules.hpp"

namespace arnoldweb {

namespace detail {

void check_state_energies(StateSet& s, const ModelDescriptor& model, const RealParams& rp, double e) {
  const std::array<double, 6> k = model.kinetic(rp);
  const std::array<double, 2> v = model.v_range(rp);
  const double scale = std::max(std::fabs(e), v[1] - v[0]);
  const double tolerance = kStateEnergyTolerance * scale;
  s.energy.assign(s.count, std::numeric_limits<double>::quiet_NaN());
  s.energy_min = std::numeric_limits<double>::infinity();
  s.energy_max = -s.energy_min;
  for (std::uint64_t i = 0; i < s.count; ++i) {
    if (s.status[i] != 0) continue;
    const double* u = &s.position_turns[3 * i];
    const double* p = &s.momentum[3 * i];
    const double h = state_energy(model, rp, k, u, p);
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

}  // namespace detail
}  // namespace arnoldweb
