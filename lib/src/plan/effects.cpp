// arnoldweb: the effect table (effects.hpp).
#include "plan/effects.hpp"

#include "arnoldweb/plan.hpp"
#include "aw_params.h"

namespace arnoldweb::detail {

namespace {
bool tracks_energy(const Scene& s) { return s.energy_error || s.max_energy_error.has_value(); }
}  // namespace

const std::vector<EffectRow>& effects() {
  static const std::vector<EffectRow> rows = {
      {"velocity_map", AW_F_VELOCITY_MAP, [](const Scene& s) { return s.velocity_map; }},
      {"energy_error", AW_F_ENERGY, tracks_energy},
      {"max_energy_error", AW_F_ENERGY_LIMIT, [](const Scene& s) { return s.max_energy_error.has_value(); }},
      {"initial_states", AW_F_INITIAL_STATES, [](const Scene& s) { return s.initial_states; }},
      {"final_states", AW_F_FINAL_STATES, [](const Scene& s) { return s.final_states; }},
      {"test_inject", AW_F_TEST_INJECT, nullptr},
      {"zoom", AW_F_ZOOM, [](const Scene& s) { return s.zoom; }},
      {"confine", AW_F_CONFINE, [](const Scene& s) { return s.confine; }},
      {"frames", AW_F_FRAMES, [](const Scene& s) { return !s.frame_times.empty(); }},
      {"time_reversal", AW_F_REVERSE, nullptr},
      {"tangent", AW_F_TANGENT, [](const Scene& s) { return s.fli || s.megno || s.lyapunov; }},
      {"fli", AW_F_FLI, [](const Scene& s) { return s.fli; }},
      {"megno", AW_F_MEGNO, [](const Scene& s) { return s.megno; }},
      {"lyapunov", AW_F_LYAPUNOV, [](const Scene& s) { return s.lyapunov; }},
      // states from a file (ensemble.initial = "file"); time slices add it when planned (plan.cpp)
      {"carry", AW_F_CARRY, [](const Scene& s) { return s.initial == "file"; }},
  };
  return rows;
}

std::uint32_t features_of(const Scene& scene) {
  std::uint32_t f = 0;
  for (const EffectRow& e : effects())
    if (e.asked && e.asked(scene)) f |= e.bit;
  return f;
}

}  // namespace arnoldweb::detail

namespace arnoldweb {

std::vector<std::string> feature_names(std::uint32_t f) {
  std::vector<std::string> n;
  for (const auto& e : detail::effects())
    if (f & e.bit) n.push_back(e.name);
  return n;
}

}  // namespace arnoldweb
