// arnoldweb: summary.json, the record of a run: what was asked, what ran
// where, what came out (counts, energy error, digests), how fast.
#include <nlohmann/json.hpp>

#include <cmath>
#include <ctime>

#include "arnoldweb/output.hpp"
#include "arnoldweb/version.hpp"
#include "output/file_digest.hpp"
#include "output_table/output_table.hpp"

namespace arnoldweb {
namespace {

using json = nlohmann::ordered_json;

json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

std::string utc_now() {
  char buf[32];
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace

std::string summary_json(const Plan& plan, const Result& r, const std::vector<std::string>& files,
                         const FileDigests* digests) {
  json j;
  j["arnoldweb"] = ARNOLDWEB_VERSION;
  j["date"] = utc_now();
  j["trajectories"] = r.trajectories;
  j["completed"] = r.completed;
  j["interrupted"] = r.interrupted;
  j["binned"] = r.binned;
  j["flagged"] = {{"total", r.flagged()},
                  {"nonfinite", r.flagged_nonfinite},
                  {"energy", r.flagged_energy},
                  {"initial", r.flagged_initial}};
  j["left_region"] = r.left_region;
  j["energy_error"] = {{"tracked", r.energy.tracked}};
  if (r.energy.tracked) {
    j["energy_error"]["max"] = r.energy.max;
    j["energy_error"]["mean"] = r.energy.mean;
    j["energy_error"]["median_upper_bound"] = number_or_null(r.energy.quantile(0.5));
    j["energy_error"]["p99_upper_bound"] = number_or_null(r.energy.quantile(0.99));
    j["energy_error"]["log_hist"] = r.energy.log_hist;
    j["energy_error"]["note"] = "max and mean over binned trajectories of max_t |E(t) - E(0)|; quantiles are "
                                "upper edges of quarter-octave histogram bins over all trajectories (log_hist: "
                                "its counts, bin 0 below 2^-64, then four bins per octave up to 2^16, the last "
                                "from 2^16 on)";
  }
  j["digests"] = {{"algorithm", "XXH3-128"}, {"map", digest_map(r)}};
  for (const std::string& name : output_names()) j["digests"][name] = digest_records(r, name);
  j["device"] = {{"id", r.device.id},
                 {"backend", r.device.backend},
                 {"name", r.device.name},
                 {"vendor", r.device.vendor},
                 {"version", r.device.version},
                 {"compute_units", r.device.compute_units}};
  j["kernel"] = r.kernel;
  j["startup"] = {{"inventory_seconds", r.startup.inventory_seconds}, {"devices", json::array()}};
  for (const DeviceStartup& s : r.startup.devices)
    j["startup"]["devices"].push_back({{"device", s.id},
                            {"open_seconds", s.open_seconds},
                            {"kernel_seconds", s.kernel_seconds},
                            {"kernel_from", s.kernel_from},
                            {"buffers_seconds", s.buffers_seconds},
                            {"first_launch_seconds", s.first_launch_seconds}});
  j["wall_seconds"] = r.wall_seconds;
  j["trajectory_steps"] = r.trajectory_steps;
  j["trajectory_steps_per_second"] = r.rate();
  j["force_evaluations_per_second"] = r.rate() * plan.method.stages;
  j["seconds_per_trajectory_per_T"] =
      r.trajectory_steps > 0 ? r.wall_seconds / (static_cast<double>(r.completed) * plan.scene.duration) : 0.0;
  j["method"] = {{"name", plan.method.name}, {"order", plan.method.order}, {"stages", plan.method.stages}};
  j["schedule"] = {{"step", plan.step},
                   {"steps_per_trajectory", plan.steps_per_trajectory},
                   {"windows", plan.windows},
                   {"segments_per_window", plan.segments_per_window},
                   {"steps_per_segment", plan.steps_per_segment}};
  j["step_guard"] = {{"value", plan.guard.value},
                     {"limit", plan.guard.limit},
                     {"advised", plan.guard.advised},
                     {"safe_step", plan.guard.safe_step},
                     {"omega", plan.guard.omega},
                     {"basis", plan.guard.basis},
                     {"overridden", plan.guard.refused() && plan.scene.allow_unsafe_step}};
  j["effects"] = plan.effects();
  j["warnings"] = plan.warning_lines();
  std::uint64_t smallest = 0, largest = 0;
  for (auto c : r.chunks) {
    smallest = smallest ? std::min(smallest, c) : c;
    largest = std::max(largest, c);
  }
  j["chunks"] = {{"count", r.chunks.size()}, {"smallest", smallest}, {"largest", largest}};
  j["maps"] = {{"nside", plan.scene.velocity_map ? plan.scene.nside : 0},
               {"ordering", "RING"},
               {"frames", plan.frames},
               {"zoom_resolution", plan.zoom_resolution}};
  for (const auto& [name, text] : r.analyses) {
    j["analyses"][name] = json::parse(text);
    // an analysis's warnings (a diffusion fit that is not diffusive) beside the plan's
    for (const json& w : j["analyses"][name].value("warnings", json::array())) j["warnings"].push_back(w);
  }
  j["time"] = {{"start", plan.start_time()}, {"end", plan.start_time() + plan.scene.duration}, {"unit", "T"}};
  j["scene"] = json::parse(plan.scene.to_json());  // every key, from the key table
  j["scene_toml"] = plan.scene.to_toml();
  if (plan.scene.auto_step.used) {  // integrator.step = "auto": the choice and its pilot (accuracy.hpp)
    const AutoStep& a = plan.scene.auto_step;
    j["auto_step"] = {{"tolerance", a.tolerance},
                      {"safety", a.safety},
                      {"method", a.method},
                      {"method_chosen", a.method_chosen},
                      {"step", a.step},
                      {"pilot_max_predicted", number_or_null(a.predicted_max)},
                      {"pilot_max", number_or_null(a.pilot_max)},
                      {"pilot_median_upper_bound", number_or_null(a.pilot_median)},
                      {"pilot_trajectories", a.pilot_trajectories},
                      {"pilot_duration", a.pilot_duration},
                      {"pilot_device", a.pilot_device},
                      {"pilot_seconds", a.pilot_seconds}};
  }
  // every file of the directory (besides summary.json itself): what --force
  // may replace, and nothing else
  j["files"] = files;
  // their sizes and digests, checked when the directory is read back
  if (digests) j["file_digests"] = detail::file_digests_json(*digests);
  // names that are not UTF-8 (paths may hold any bytes) are written with U+FFFD
  return j.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace arnoldweb
