// arnoldweb: the effect table (effects.hpp).
#include "plan/effects.hpp"

#include <map>
#include <stdexcept>

#include "arnoldweb/plan.hpp"
#include "aw_params.h"
#include "output_table/output_table.hpp"

namespace arnoldweb::detail {

namespace {
bool tracks_energy(const Scene& s) { return s.energy_error || s.max_energy_error.has_value(); }

// The rows with one per switch and per table key of the output table (asked
// through features_of), each before the first row of a higher bit; then `last`.
std::vector<EffectRow> with_outputs(std::vector<EffectRow> rows, const std::vector<EffectRow>& last) {
  const auto insert = [&rows](const std::string& name, std::uint32_t bit) {
    auto at = rows.begin();
    while (at != rows.end() && at->bit < bit) ++at;
    rows.insert(at, EffectRow{name, bit, nullptr});
  };
  for (const OutputSwitch* w : output_switches()) insert(w->effect(), w->bit);
  for (const KeyTable* t : key_tables()) insert(t->effect(), t->bit);
  rows.insert(rows.end(), last.begin(), last.end());
  return rows;
}
}  // namespace

const std::vector<EffectRow>& effects() {
  static const std::vector<EffectRow> rows = with_outputs({
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
      // the output table's switches and table keys ask for their own bits as well (features_of)
      {"tangent", AW_F_TANGENT, nullptr},  // the indicators' switches need it
  }, {
      // states from a file (ensemble.initial = "file"); time slices add it when planned (plan.cpp)
      {"carry", AW_F_CARRY, [](const Scene& s) { return s.initial == "file"; }},
  });
  return rows;
}

std::uint32_t features_of(const Scene& scene, std::uint32_t switch_bits) {
  std::uint32_t f = switch_bits;
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

std::vector<std::string> output_names() {
  std::vector<std::string> names;
  for (const detail::RecordOutput& r : detail::record_outputs())
    if (!r.internal()) names.push_back(r.name);
  return names;
}

std::vector<std::string> output_fields(const std::string& output) {
  const detail::RecordOutput* row = detail::find_record_output(output);
  if (!row || row->internal()) throw std::invalid_argument("no output named \"" + output + "\"");
  std::map<int, std::string> by_column;
  for (const detail::RecordDataset& d : row->datasets)
    if (!d.integers && (d.count != 1 || !by_column.emplace(d.first, d.name).second)) return {};
  std::vector<std::string> names;
  for (const auto& [column, name] : by_column) {
    if (column != static_cast<int>(names.size())) return {};  // a column without a name
    names.push_back(name);
  }
  return names;
}

}  // namespace arnoldweb
