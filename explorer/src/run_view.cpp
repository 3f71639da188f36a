#include "run_view.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "arnoldweb/analysis.hpp"
#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "arnoldweb/plan.hpp"
#include "run_fields.hpp"

namespace arnoldweb::explorer {
namespace {

template <typename T>
void append_as(std::string& out, const std::vector<std::uint64_t>& counts) {
  out.resize(counts.size() * sizeof(T));
  char* p = out.data();
  for (std::uint64_t c : counts) {
    const T v = static_cast<T>(c);
    std::memcpy(p, &v, sizeof(T));  // x86-64 and every platform arnoldweb builds on: little-endian
    p += sizeof(T);
  }
}

std::string short_number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

nlohmann::json region_of(const Scene& s) {
  if (s.initial == "cap") return {{"kind", "cap"}, {"center", s.cap_center}, {"radius", s.cap_radius}};
  if (s.initial == "box") return {{"kind", "box"}, {"lon", s.box_lon}, {"lat", s.box_lat}};
  return nullptr;
}

}  // namespace

std::string map_bytes(const std::vector<std::uint64_t>& counts, std::string* dtype) {
  const std::uint64_t top = counts.empty() ? 0 : *std::max_element(counts.begin(), counts.end());
  std::string out;
  if (top <= 0xFF) {
    *dtype = "u8";
    append_as<std::uint8_t>(out, counts);
  } else if (top <= 0xFFFF) {
    *dtype = "u16";
    append_as<std::uint16_t>(out, counts);
  } else if (top <= 0xFFFFFFFFull) {
    *dtype = "u32";
    append_as<std::uint32_t>(out, counts);
  } else {  // exact up to 2^53
    *dtype = "f64";
    out.resize(counts.size() * sizeof(double));
    for (std::size_t i = 0; i < counts.size(); ++i) {
      const double v = static_cast<double>(counts[i]);
      std::memcpy(out.data() + i * sizeof(double), &v, sizeof(double));
    }
  }
  return out;
}

RunView read_run_view(const std::string& dir, const std::string& id) {
  RunView v;
  v.dir = dir;
  v.id = id;
  const nlohmann::json summary = nlohmann::json::parse(read_saved_summary(dir));
  const std::string summary_file = dir + "/summary.json";
  if (!summary.contains("scene_toml") || !summary["scene_toml"].is_string())
    throw SavedRunError(summary_file, "holds no scene_toml (the scene as run), which the explorer shows runs by");
  try {
    v.scene = parse_scene(summary["scene_toml"].get<std::string>(), summary_file + " (scene_toml)");
  } catch (const SceneError& e) {
    throw SavedRunError(summary_file, std::string("its scene_toml does not read as a scene: ") + e.what());
  }
  const Scene& s = v.scene;
  std::string title = std::filesystem::path(dir).lexically_normal().filename().string();
  if (title.empty()) title = std::filesystem::path(dir).lexically_normal().parent_path().filename().string();
  nlohmann::json meta;
  meta["id"] = id;
  meta["title"] = title;
  meta["description"] = "E = " + short_number(s.energy) + ", " + s.model_kind + ", " + s.method + " h = " +
                        short_number(s.step) + " T, dt = " + short_number(s.average) + " T, " +
                        std::to_string(summary.value("completed", std::uint64_t{0})) + " trajectories (" +
                        s.initial + ")";
  meta["scene"] = {{"energy", s.energy},         {"model", s.model_kind},   {"method", s.method},
                   {"step", s.step},             {"average", s.average},    {"duration", s.duration},
                   {"trajectories", s.trajectories}, {"seed", s.seed},     {"initial", s.initial},
                   {"region", region_of(s)},     {"nside", s.nside},        {"velocity_map", s.velocity_map}};
  meta["binned"] = summary.value("binned", std::uint64_t{0});
  if (summary.contains("digests") && summary["digests"].is_object()) meta["digests"] = summary["digests"];
  // the resonances of the model's harmonics (map_resonances.png draws the same), or null:
  // every circle of low order
  nlohmann::json model = {{"kind", s.model_kind}, {"resonances", nullptr}};
  try {
    const auto vectors = model_resonances(make_plan(s));
    if (!vectors.empty()) model["resonances"] = vectors;
  } catch (const Error& e) {
    model["note"] = std::string("the model's resonances are not known: ") + e.what();
  }
  meta["model"] = model;
  if (s.velocity_map && summary.contains("maps")) {
    SavedMaps maps = read_saved_maps(dir);
    if (!maps.map.empty()) {
      std::string dtype;
      v.map_bytes = map_bytes(maps.map, &dtype);
      v.counts = std::move(maps.map);
      meta["map"] = {{"nside", maps.nside}, {"dtype", dtype}, {"count", v.counts.size()}};
    }
  }
  if (!meta.contains("map")) meta["map"] = nullptr;
  v.fields = read_run_fields(dir, summary, s);
  meta["fields"] = nlohmann::json::array();
  for (const auto& [name, f] : v.fields.items())
    if (name != "frequencies") meta["fields"].push_back(name);
  meta["frequencies"] = v.fields.contains("frequencies");
  v.meta = std::move(meta);
  return v;
}

nlohmann::json compare_json(const RunView& a, const RunView& b) {
  if (a.counts.empty() || b.counts.empty() || a.counts.size() != b.counts.size())
    throw SavedRunError(b.dir, "the maps of " + a.id + " and " + b.id + " are not of one resolution: nothing to compare");
  const MapComparison c = compare_maps(a.counts, b.counts);
  nlohmann::json j = {{"a", a.id}, {"b", b.id}, {"chi2", c.chi2}, {"dof", c.dof}, {"p_value", c.p_value},
                      {"total_a", c.total_a}, {"total_b", c.total_b}, {"used_bins", c.used_bins},
                      {"pooled_bins", c.pooled_bins}};
  if (a.scene.seed == b.scene.seed)
    j["note"] = "both runs have ensemble.seed = " + std::to_string(a.scene.seed) +
                ": if their initial states agree, the maps are not independent samples and the test is too lenient";
  return j;
}

}  // namespace arnoldweb::explorer
