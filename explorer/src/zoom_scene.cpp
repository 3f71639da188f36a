#include "zoom_scene.hpp"

#include <cmath>
#include <cstdio>

namespace arnoldweb::explorer {
namespace {

std::string number(const nlohmann::json& v, const std::string& field) {
  if (!v.is_number()) throw BadRequest("region." + field + " must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw BadRequest("region." + field + " must be finite");
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  std::string s(b);
  if (s.find_first_of(".eE") == std::string::npos) s += ".0";  // a TOML float
  return s;
}

std::string pair(const nlohmann::json& r, const std::string& field) {
  if (!r.contains(field) || !r[field].is_array() || r[field].size() != 2)
    throw BadRequest("region." + field + " must be an array of two numbers");
  return "[" + number(r[field][0], field + "[0]") + ", " + number(r[field][1], field + "[1]") + "]";
}

}  // namespace

std::vector<std::string> region_overrides(const nlohmann::json& r) {
  if (!r.is_object() || !r.contains("kind") || !r["kind"].is_string())
    throw BadRequest("region must be an object with kind \"cap\" or \"box\"");
  const std::string kind = r["kind"];
  if (kind == "cap") {
    if (!r.contains("radius")) throw BadRequest("region.radius is missing");
    return {"ensemble.initial=\"cap\"", "ensemble.cap.center=" + pair(r, "center"),
            "ensemble.cap.radius=" + number(r["radius"], "radius")};
  }
  if (kind == "box")
    return {"ensemble.initial=\"box\"", "ensemble.box.lon=" + pair(r, "lon"), "ensemble.box.lat=" + pair(r, "lat")};
  throw BadRequest("region.kind must be \"cap\" or \"box\", not \"" + kind + "\"");
}

Scene zoom_scene(const Scene& source, const nlohmann::json& region, std::uint64_t trajectories, int nside,
                 const std::string& out_dir) {
  Scene s = source;
  s.panels.clear();  // a zoom is one run
  std::vector<std::string> sets = region_overrides(region);
  sets.push_back("ensemble.trajectories=" + std::to_string(trajectories));
  if (nside) sets.push_back("observe.velocity_map.nside=" + std::to_string(nside));
  sets.push_back(string_override("output.dir", out_dir, "the zoom's directory " + out_dir));
  // the scene reader checks every value, as for a scene file; the text it keeps (to_toml with
  // the overrides applied) is what summary.json records
  const Scene parsed = parse_scene(s.to_toml(), "zoom of " + source.output_dir, sets);
  return parse_scene(parsed.to_toml(), "zoom of " + source.output_dir);
}

}  // namespace arnoldweb::explorer
