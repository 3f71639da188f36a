// arnoldweb: continuing a finished run (output.hpp: continuation_of,
// continue_keys). The run's scene as it ran, started from its states.h5 for
// more time: the values it adds are written as TOML values (quoted strings,
// exact doubles), so a directory's name is never read as TOML; and the keys a
// caller may add are those that leave the trajectories unchanged.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "output/saved_run.hpp"
#include "output_table/output_table.hpp"
#include "scene/scene_internal.hpp"  // toml_double, show_double

namespace arnoldweb {
namespace {

using scene_detail::show_double;
using scene_detail::toml_double;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

bool under(const std::string& key, const std::string& prefix) {
  return key == prefix || key.compare(0, prefix.size() + 1, prefix + ".") == 0;
}

// The caller's overrides, each of a key that continuing allows.
void check_sets(const ContinueArgs& args) {
  for (std::size_t k = 0; k < args.sets.size(); ++k) {
    const std::string& text = args.sets[k];
    const std::string key = trim(text.substr(0, text.find('=')));
    const std::string label =
        k < args.set_labels.size() && !args.set_labels[k].empty() ? args.set_labels[k] : "--set " + text;
    if (key == "run.duration")
      throw SceneError(label, 0, 0, key,
                       "a continuation runs for the duration it is given (--for DURATION; continue_run(out_dir, "
                       "duration)), not run.duration: give the one or the other, not both");
    const auto& allowed = continue_keys();
    if (std::none_of(allowed.begin(), allowed.end(), [&](const std::string& a) { return under(key, a); })) {
      std::string list;
      for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
      throw SceneError(label, 0, 0, key,
                       "a continuation keeps the run's trajectories, so it may set only keys that leave them "
                       "unchanged (" + list + "; docs/cluster.md). To integrate the final states otherwise, "
                       "start a new run from them: ensemble.initial = \"file\" with ensemble.file = "
                       "\"<the run's directory>/states.h5\"");
    }
  }
}

}  // namespace

const std::vector<std::string>& continue_keys() {
  // Not: model.*, integrator.*, ensemble.* but chunk (they make other trajectories), run.duration
  // (the duration is the continuation's own), observe.max_energy_error and observe.confine (they
  // flag trajectories, whose status the final states carry).
  // The output table's switches, table keys and direction keys too (an output leaves the trajectories as they are).
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k = {
        "run.device",           "run.checkpoint_every", "run.slice",         "run.average",
        "ensemble.chunk",       "observe.velocity_map", "observe.energy_error", "observe.initial_states",
        "observe.final_states", "observe.zoom",         "observe.frames",
        "output.dir",           "output.images"};
    for (const detail::OutputSwitch* w : detail::output_switches()) k.push_back(w->key);
    for (const detail::KeyTable* t : detail::key_tables()) k.push_back(t->key);
    for (const detail::DirectionKey* d : detail::direction_keys()) k.push_back(d->key);
    return k;
  }();
  return keys;
}

Continuation continuation_of(const std::string& dir, const ContinueArgs& args) {
  check_sets(args);
  const detail::SavedDir saved(dir);
  Continuation c;
  c.source = saved.summary_path();
  c.scene_toml = saved.text("/scene_toml");
  const nlohmann::json& time = saved.summary().value("time", nlohmann::json::object());
  if (time.is_object() && time.contains("end") && time["end"].is_number()) c.end_time = time["end"].get<double>();
  const std::string states = saved.path("states.h5");
  std::error_code ec;
  if (!std::filesystem::exists(states, ec))
    throw SavedRunError(states, "the run kept no final states to continue from: run it with "
                                "observe.final_states = true");
  if (saved.checked() && !saved.recorded("states.h5"))
    throw SavedRunError(states, "summary.json records no digest for it: it is not a file the run wrote");
  const std::string from = "continue " + dir, duration = show_double(args.duration);
  c.overrides = {"ensemble.initial=\"file\"", string_override("ensemble.file", states, from),
                 "run.duration=" + toml_double(args.duration)};
  c.labels = {from, from, "continue for " + duration + " T"};
  for (std::size_t k = 0; k < args.sets.size(); ++k) {
    c.overrides.push_back(args.sets[k]);
    c.labels.push_back(k < args.set_labels.size() ? args.set_labels[k] : std::string());
  }
  std::optional<std::string> out = args.out;
  if (!out && args.out_beside) {
    out = dir + "-to-" + show_double(c.end_time + args.duration);
  }
  if (out) {
    c.overrides.push_back(string_override("output.dir", *out, "--out " + *out));
    c.labels.push_back("--out " + *out);
  }
  if (args.device) {
    c.overrides.push_back(string_override("run.device", *args.device, "--device " + *args.device));
    c.labels.push_back("--device " + *args.device);
  }
  return c;
}

}  // namespace arnoldweb
